#pragma once

#include <string>

#include "proto/pipeline_options.pb.h"

namespace areagraph {

// Every option that can be judged without a map is checked here, so that a
// tool fails on bad options before it touches the store. What depends on the
// map's frame (a width wider than the map, metres to pixels) is checked
// where the options are converted to pixels (e.g. CleanParametersFor,
// RoomWidthM). Each check throws OptionsError naming the first bad option.

// Largest accepted resolution. Anything coarser than a kilometre per pixel is
// a typo (or a unit mix-up), not a map.
inline constexpr double kMaxResolutionM = 1000.0;

// Throws unless `resolution_m` is finite, positive and at most
// kMaxResolutionM: OptionsError when it came from an option, else
// InputError. `what` names its source.
void CheckResolution(double resolution_m, const std::string& what, bool is_option);

void CheckImportOptions(const proto::ImportOptions& options);
void CheckCleanOptions(const proto::CleanOptions& options);
void CheckPruneOptions(const proto::PruneOptions& options);
void CheckCutOptions(const proto::CutOptions& options);
void CheckMergeOptions(const proto::MergeOptions& options);
void CheckMatchOptions(const proto::MatchOptions& options);

// All of the above: what every tool calls before it opens the store.
void CheckPipelineOptions(const proto::PipelineOptions& options);

}  // namespace areagraph

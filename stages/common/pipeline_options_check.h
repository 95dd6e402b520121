#pragma once

#include <string>

#include "proto/pipeline_options.pb.h"

namespace areagraph {

// Every option that can be judged without a map is checked here, so that a
// tool fails on bad options before it touches the store. What depends on the
// map's frame (a width wider than the map, metres to pixels) is checked
// where the options are converted to pixels (e.g. CleanParametersFor,
// RoomWidthM). Each check throws OptionsError naming the first bad option.

// Accepted resolutions. Anything coarser than a kilometre per pixel, or finer
// than a tenth of a millimetre, is a typo (or a unit mix-up), not a building
// map; beyond them lengths in pixels overflow.
inline constexpr double kMinResolutionM = 1e-4;
inline constexpr double kMaxResolutionM = 1000.0;

// Throws unless `resolution_m` is finite and within [kMinResolutionM,
// kMaxResolutionM]: OptionsError when it came from an option, else
// InputError. `what` names its source.
void CheckResolution(double resolution_m, const std::string& what, bool is_option);

void CheckImportOptions(const proto::ImportOptions& options);
void CheckCleanOptions(const proto::CleanOptions& options);
void CheckPruneOptions(const proto::PruneOptions& options);
void CheckCutOptions(const proto::CutOptions& options);
void CheckMergeOptions(const proto::MergeOptions& options);
void CheckMatchOptions(const proto::MatchOptions& options);

// What depends on the map: merge.outline_tolerance_m must stay below half
// the room width W that cut used (`room_width_m`; 0 when unknown), else an
// outline may stray across a room to its other wall and leave slivers.
void CheckOutlineTolerance(const proto::MergeOptions& options, double room_width_m);

// All of the above: what every tool calls before it opens the store.
void CheckPipelineOptions(const proto::PipelineOptions& options);

}  // namespace areagraph

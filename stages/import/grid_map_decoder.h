#pragma once

#include <array>
#include <cstdint>
#include <opencv2/core.hpp>
#include <string>

#include "proto/artifacts.pb.h"
#include "proto/pipeline_options.pb.h"
#include "stages/import/map_yaml.h"

namespace areagraph {

// The CellState of each 8-bit grey value. Every rule that turns a grey image
// into cells depends on the grey value alone, so one table serves them all.
using GreyToCell = std::array<proto::CellState, 256>;

// The rule for maps without a YAML (Bormann's convention, widened):
//   grey >= free_min_grey     -> free      (default 250: white 255, and 254 as
//                                           in some published scans)
//   grey <= occupied_max_grey -> occupied  (default 100: walls are 0 or
//                                           anti-aliased dark grey)
//   anything in between       -> unknown   (unknown/outside 103..230 and
//                                           light furniture 211 in the
//                                           Bormann, Area Graph and MAORIS maps)
// Throws OptionsError for bad import options (CheckImportOptions), e.g.
// unless 0 <= occupied_max_grey < free_min_grey <= 255.
GreyToCell GreyThresholdRule(const proto::ImportOptions& options);

// ROS map_server's rule for the thresholds and mode in `yaml`: with v the grey
// value (255 - v when negate), p = (255 - v) / 255; p > occupied_thresh is
// occupied, p < free_thresh is free, the rest unknown. Mode raw reads v as an
// occupancy percentage instead, p = v / 100, with v > 100 unknown.
// Mode scale has no unknown value besides transparency in ROS; since alpha
// is dropped on import it classifies like trinary.
GreyToCell MapServerRule(const MapYaml& yaml);

// One CellState byte per pixel, row-major from the top row of `grey` (CV_8UC1).
std::string ClassifyCells(const cv::Mat& grey, const GreyToCell& rule);

}  // namespace areagraph

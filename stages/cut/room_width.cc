#include "stages/cut/room_width.h"

#include <cmath>
#include <string>

#include "common/error.h"
#include "common/text.h"
#include "stages/common/pipeline_options_check.h"
#include "stages/cut/width_estimate.h"

namespace areagraph {
namespace {

void CheckFitsMap(double width, const proto::MapFrame& frame) {
  const double map_width_m = frame.width_px() * frame.resolution_m();
  const double map_height_m = frame.height_px() * frame.resolution_m();
  if (width > std::max(map_width_m, map_height_m)) {
    throw OptionsError("the room width W = " + FormatNumber(width) + " m is wider than the map (" +
                       FormatNumber(map_width_m) + " x " + FormatNumber(map_height_m) + " m)");
  }
}

}  // namespace

double RoomWidthM(const proto::CutOptions& options, const proto::MapFrame& frame) {
  CheckCutOptions(options);
  const double door = options.door_width_m();
  const double corridor = options.corridor_width_m();
  double width = options.room_width_m();
  if (door > 0 && corridor > 0) width = door < corridor ? door + 0.1 : corridor - 0.1;
  CheckFitsMap(width, frame);
  return width;
}

proto::RoomWidthEstimate ChooseRoomWidth(const proto::CutOptions& options,
                                         const proto::MapFrame& frame,
                                         const proto::TopologyGraph& topology) {
  const double fixed = RoomWidthM(options, frame);
  const bool strategy = options.door_width_m() > 0 && options.corridor_width_m() > 0;
  proto::RoomWidthEstimate estimate;
  if (options.room_width_auto() && !strategy) {
    estimate =
        EstimateRoomWidth(topology, frame.resolution_m(), fixed, options.room_width_above_doors());
    CheckFitsMap(estimate.room_width_m(), frame);
  } else {
    estimate.set_room_width_m(fixed);
    estimate.set_automatic(false);
  }
  return estimate;
}

}  // namespace areagraph

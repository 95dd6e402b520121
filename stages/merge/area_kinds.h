#pragma once

#include "proto/artifacts.pb.h"
#include "stages/merge/area_assignment.h"
#include "stages/merge/area_raster.h"

namespace areagraph {

// The kind of every area of the final plan, from its shape in `raster`
// (RasterShape) and its exits (the graph vertices where it meets other
// areas), as PlanModel::Corridor has it for the passes:
// - a corridor is a way through (two exits or more) and is shaped like a
//   corridor (IsCorridorShaped), or has no room (the room disk fits nowhere
//   in it: a piece of the corridors between junctions, narrower than W);
// - a dead end has no room and one exit at most;
// - everything else is a room (a long room with one door too).
// Each area's `kind` is set; `room_id` and the edges stay. `furniture`
// (optional) is RasterShape's.
void SetAreaKinds(const proto::CutGraph& graph, const AreaRaster& raster, double resolution_m,
                  AreaPlan* plan, const cv::Mat& furniture = cv::Mat());

}  // namespace areagraph

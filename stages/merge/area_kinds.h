#pragma once

#include "proto/artifacts.pb.h"
#include "stages/merge/area_assignment.h"
#include "stages/merge/area_raster.h"

namespace areagraph {

// The kind of every area of the final plan, from its shape in `raster`
// (RasterShape) and its exits (the graph vertices where it meets other
// areas):
// - a corridor is shaped like a corridor (IsCorridorShaped) and is a way
//   through (two exits or more), as PlanModel::Corridor has it for the
//   passes;
// - a dead end is shaped like a corridor and has one exit at most: a
//   corridor that ends blind;
// - everything else is a room. Whether the room disk fits does not matter:
//   a closet or a stair core narrower than W is a small room, and a short
//   narrow link between two areas is no corridor either.
// Each area's `kind` is set; `room_id` and the edges stay. `furniture`
// (optional) is RasterShape's.
void SetAreaKinds(const proto::CutGraph& graph, const AreaRaster& raster, double resolution_m,
                  AreaPlan* plan, const cv::Mat& furniture = cv::Mat());

}  // namespace areagraph

#pragma once

#include <cstdint>
#include <functional>
#include <opencv2/core.hpp>
#include <vector>

#include "proto/artifacts.pb.h"
#include "stages/merge/area_assignment.h"
#include "stages/merge/furniture_islands.h"
#include "stages/merge/plan_model.h"

namespace areagraph {

// Joins areas that meet at a graph vertex where the opening between them has
// an island for a jamb: a door is cut into a wall, so a gap between a desk
// and a wall, or between two desks, is no door but furniture standing in one
// room. Two rooms are joined at such a gap; a room-less area (a strip between
// desks that the room disk could not enter) is joined only when every one of
// its openings is such a gap, so that a corridor whose door has a desk beside
// it stays a corridor; room-less areas are joined with each other at gaps
// (clutter in a corridor) unless one of them is part of a room by then. The
// smaller of the two areas must be at most `max_piece_m2`
// (merge.corridor_pieces.below_m2, the size below which a space that opens
// widely is a piece of a bigger one): a room cut off by a row of blocks with
// openings between them (a glass wall on pillars) is bigger than the strip
// beside a desk. A joined area is a room when one of its parts was. No areas
// join at a `closed` vertex (a cut ag-cut made on a door or wall gap it
// closed, ClosedVertices): a desk beside such a door is no jamb.
//
// `islands_at` gives the islands' values (FurnitureIslandCells's, non-zero
// on an island) at the cells asked, all at once; the overload below reads
// them from a raster.
using IslandsAt = std::function<std::vector<uint8_t>(const std::vector<cv::Point>& cells)>;
void JoinAreasAtFurnitureGaps(const proto::CutGraph& graph, const PlanModel& model,
                              const std::vector<bool>& closed, const IslandsAt& islands_at,
                              double max_piece_m2, AreaPlan* plan);
void JoinAreasAtFurnitureGaps(const proto::CutGraph& graph, const PlanModel& model,
                              const std::vector<bool>& closed, const cv::Mat& islands,
                              double max_piece_m2, AreaPlan* plan);

}  // namespace areagraph

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

// The smaller of two areas at a gap is at most this big (m2, its edges'
// polygons): a room cut off by a row of blocks with openings between them
// (a glass wall on pillars) is bigger than the strip beside a desk. The size
// below which a room that opens widely is a piece of a corridor, too
// (merge.corridor_pieces.below_m2, 20).
inline constexpr double kMaxFurnitureGapPieceM2 = 20.0;

// Joins areas that meet at a graph vertex where the opening between them has
// an island for a jamb: a door is cut into a wall, so a gap between a desk
// and a wall, or between two desks, is no door but furniture standing in one
// room. Two rooms are joined at such a gap; a room-less area (a strip between
// desks that the room disk could not enter) is joined only when every one of
// its openings is such a gap, so that a corridor whose door has a desk beside
// it stays a corridor; room-less areas are joined with each other at gaps
// (clutter in a corridor) unless one of them is part of a room by then. The
// smaller of the two areas must be at most kMaxFurnitureGapPieceM2. A joined
// area is a room when one of its parts was. No areas join at a `closed`
// vertex (a cut ag-cut made on a door or wall gap it closed,
// ClosedVertices): a desk beside such a door is no jamb.
//
// `islands_at` gives the islands' values (FurnitureIslandCells's, non-zero
// on an island) at the cells asked, all at once; the overload below reads
// them from a raster.
using IslandsAt = std::function<std::vector<uint8_t>(const std::vector<cv::Point>& cells)>;
void JoinAreasAtFurnitureGaps(const proto::CutGraph& graph, const PlanModel& model,
                              const std::vector<bool>& closed, const IslandsAt& islands_at,
                              AreaPlan* plan);
void JoinAreasAtFurnitureGaps(const proto::CutGraph& graph, const PlanModel& model,
                              const std::vector<bool>& closed, const cv::Mat& islands,
                              AreaPlan* plan);

}  // namespace areagraph

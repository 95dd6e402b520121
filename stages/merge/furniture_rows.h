#pragma once

#include <opencv2/core.hpp>
#include <vector>

#include "proto/artifacts.pb.h"
#include "stages/merge/area_assignment.h"
#include "stages/merge/plan_model.h"

namespace areagraph {

// Rows stand in a stack, at most this far apart centre to centre (metres):
// seats about 1 m, the shelves of a library or store under 2 m. A piece of
// wall between two doors has a room on either side instead.
inline constexpr double kMaxRowPitchM = 2.0;
// A stack has at least this many rows: two walls of a corridor, broken off
// at doors on both ends, stand side by side too.
inline constexpr int kMinStackRows = 3;

// Which obstacle cells belong to a furniture row, as CV_8U the map's size
// (1 on row cells): a free-standing obstacle region (touching no image
// border) at least kMinFurnitureThicknessM thick
// (furniture_islands.h), but more than `min_elongation` times as long as
// wide, in a stack of at least kMinStackRows such regions (each beside the
// next: overlapping along its axis, within kMaxRowPitchM across). Alone, such a block is no
// island (a thick piece of wall between two doors); a stack of them is the furniture of one room,
// and the strips between them are no rooms. The map's wall thickness does not enter: rows of seats
// are often no thicker than two walls.
cv::Mat FurnitureRowCells(const proto::CleanedMap& map, double min_elongation);

// Joins areas at openings where a row of `rows` (FurnitureRowCells; empty
// for none) is a jamb, as JoinAreasAtFurnitureGaps joins them at islands,
// (the smaller area at most `max_piece_m2`), also at a cut that ag-cut
// closed (`closed`): it took the row's end for a
// wall's, and the aisle beside it for a door.
void JoinAreasAtFurnitureRows(const proto::CutGraph& graph, const PlanModel& model,
                              const cv::Mat& rows, std::vector<bool> closed, double max_piece_m2,
                              AreaPlan* plan);

}  // namespace areagraph

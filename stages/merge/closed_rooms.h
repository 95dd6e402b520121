#pragma once

#include <cstdint>
#include <vector>

#include "proto/artifacts.pb.h"
#include "stages/geometry/cell_grid.h"
#include "stages/merge/area_assignment.h"
#include "stages/merge/area_raster.h"

namespace areagraph {

// A jamb's thickness is measured this far beyond it on the opening's line:
// more than a wall's end is rounded off by the scan, less than a cabinet's
// depth (about 0.6 m).
inline constexpr double kJambDepthM = 0.25;

// Per area of `plan`: whether it is a small closed room that
// FoldSmallAreas keeps although it has fewer than `min_cells` cells (and
// some). All must hold:
// - it meets the other areas at one graph vertex only, and one area there;
// - that vertex is `closed` (ag-cut closed that passage on purpose,
//   ClosedVertices);
// - its opening there is narrower than 1 - kSameWidthShare (a door) of its widest
//   inner width (twice the largest distance from its cells to a cell
//   outside it);
// - at most kMissedWallShare (stages/geometry/wall_thickness.h) of its faces
//   towards non-free cells face unknown cells (cells off the map count as
//   unknown): a room's walls were seen; a piece that borders unknown space is
//   a scan's frontier or gap, not a room;
// - unless `pocket_jamb_m` is 0, not both of its jambs are obstacles at
//   least `pocket_jamb_m` thick kJambDepthM beyond the opening (across its
//   line): a door's jambs are a wall's ends, thin with free space on both
//   sides; a pocket between cabinets is entered past their corners or along
//   their faces.
std::vector<bool> SmallClosedRooms(const proto::CutGraph& graph, const AreaPlan& plan,
                                   const AreaRaster& raster, const CellGrid& grid,
                                   const std::vector<bool>& closed, int64_t min_cells,
                                   double pocket_jamb_m);

}  // namespace areagraph

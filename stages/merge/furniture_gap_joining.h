#pragma once

#include <opencv2/core.hpp>
#include <string>

#include "proto/artifacts.pb.h"
#include "stages/merge/area_assignment.h"

namespace areagraph {

// Obstacle regions (8-connected non-free cells) that touch no image border
// and whose bounding box is at most this long (metres) are islands: desks,
// cabinets, shelves and tables standing free. The building's walls are one
// region with the map's outside, or longer.
inline constexpr double kMaxFurnitureIslandM = 4.0;
// Islands are at least this thick (metres; twice the depth of their deepest
// cell) and kFurnitureWallRatio times the map's typical wall: noise specks
// and pieces of wall between two doors are thinner.
inline constexpr double kMinFurnitureThicknessM = 0.3;
inline constexpr double kFurnitureWallRatio = 2.0;
// Islands fill at least this share of their smallest enclosing rectangle: a
// piece of wall with a T or a cabinet against it does not.
inline constexpr double kMinFurnitureSolidity = 0.75;

// Which obstacle cells belong to an island, as CV_8U the map's size (1 on
// island cells). Cells that cleaning removed count as obstacles, so that a
// wall it broke stays one region. Free pockets enclosed by obstacles and at
// most `fill_pockets_m` long (merge.fill_furniture_outlines_m) count as
// obstacles too, so that a desk drawn as a closed outline is one solid
// island; 0 leaves them free.
// Free-standing islands are 1. With `against_walls`
// (merge.wall_furniture_islands), what stands against a thin wall is marked
// 2: the same tests on what is left of the obstacles once everything thinner
// than an island is taken away (a morphological opening with a disk as wide
// as the least island thickness), so that a bin or a cabinet touching a
// corridor's wall is no door's jamb. Islands are at most `max_elongation`
// (merge.furniture_max_elongation) times as long as their smallest enclosing
// rectangle is wide, 0 for any shape: a thick piece of wall between two
// doors is no desk.
cv::Mat FurnitureIslandCells(const proto::CleanedMap& map, double fill_pockets_m,
                             bool against_walls, double max_elongation);

// The smaller of two areas at a gap is at most this big (m2, its edges'
// polygons): a room cut off by a row of blocks with openings between them
// (a glass wall on pillars) is bigger than the strip beside a desk.
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
// area is a room when one of its parts was. With `keep_closed_doors`, no
// areas join at a cut ag-cut made on a door or wall gap it closed
// (PassagePoint.closed_by_cut): a desk beside such a door is no jamb. With
// `corridor_clutter` (merge.join_corridor_clutter), two rooms that are both
// shaped like corridors (CorridorLike, stages/merge/room_joining.h) join
// where the opening's jamb stands against a wall (2 in `islands`; elsewhere
// only free-standing islands count) whatever their size, also at a closed
// cut (ag-cut closes a narrowing between two wider spaces whose sides are
// structure, which a bin against a wall makes): a bin in a corridor does
// not divide it.
void JoinAreasAtFurnitureGaps(const proto::CutGraph& graph, const cv::Mat& islands,
                              double resolution_m, bool keep_closed_doors, bool corridor_clutter,
                              AreaPlan* plan);

}  // namespace areagraph

#pragma once

#include <cstdint>
#include <opencv2/core.hpp>
#include <vector>

#include "proto/artifacts.pb.h"
#include "stages/geometry/furniture_shape.h"
#include "stages/geometry/wall_thickness.h"

namespace areagraph {

// Obstacle regions (8-connected non-free cells) that touch no image border
// and whose bounding box is at most `max_length_m` long are islands: desks,
// cabinets, shelves and tables standing free. The building's walls are one
// region with the map's outside, or longer. ag-merge passes ag-cut's
// cut.islands.max_length_m (CutGraph.island_max_length_m): one length tells
// furniture from structure in both stages.
// Islands are at least kMinFurnitureThicknessM thick (twice the depth of
// their deepest cell) and kFurnitureWallRatio times the map's typical wall
// (stages/geometry/wall_thickness.h): noise specks and pieces of wall between
// two doors are thinner. Islands fill at least kMinFurnitureSolidity of their
// smallest enclosing rectangle (stages/geometry/furniture_shape.h).

// The map's non-free cells (ObstacleMask) plus the cells that cleaning
// removed: what cleaning removed is still no free space, so a wall it broke
// stays one region.
cv::Mat ObstaclesBeforeCleaning(const proto::CleanedMap& map);

// Which obstacle cells belong to an island, as CV_8U the map's size (1 on
// island cells). Cells that cleaning removed count as obstacles, so that a
// wall it broke stays one region. With `fill_outlines`, free pockets enclosed
// by obstacles and at most `max_length_m` long (a desk drawn as an outline is
// no longer than an island) count as obstacles too, so that a desk drawn as a
// closed outline is one solid island. Islands are at most `max_elongation` times as
// long as their smallest enclosing rectangle is wide, 0 for any shape: a
// thick piece of wall between two doors is no desk (both:
// merge.furniture_gaps).
cv::Mat FurnitureIslandCells(const proto::CleanedMap& map, double max_length_m, bool fill_outlines,
                             double max_elongation);

// FurnitureIslandCells's values at `cells` only (0 for a cell outside the
// map). Only the regions that hold one of them are walked, each only as far
// as it can still be an island (a wall stops at the island's length): merge
// asks about the jambs of its openings, a few thousand cells of millions.
std::vector<uint8_t> FurnitureIslandsAt(const proto::CleanedMap& map, double max_length_m,
                                        bool fill_outlines, double max_elongation,
                                        const std::vector<cv::Point>& cells);

}  // namespace areagraph

#pragma once

#include <cstdint>
#include <opencv2/core.hpp>
#include <string>
#include <vector>

#include "proto/geometry.pb.h"
#include "stages/clean/wall_pieces.h"

namespace areagraph {

// What furniture removal took out of the grid.
struct FurnitureRemoval {
  // Flat cell indices, increasing.
  std::vector<int> removed_cells;
  // One convex outline (around the cells' squares, pixel coordinates) per
  // removed piece, for drawing.
  std::vector<proto::Polygon> shapes;
};

// Step (b) of the paper's preprocessing. The alpha shape (disk radius
// alpha_radius_px) of the obstacle cells splits them into pieces; a piece
// whose boundary (ComponentPerimeters) is shorter than max_perimeter_px is
// furniture and all its cells become free. Obstacles closer together than
// the disk's diameter (the robot width) join into one piece, so furniture
// standing by a wall stays as part of it.
//
// Obstacle cells are occupied AND unknown cells: the Bormann maps draw
// furniture in light grey, which imports as unknown, and small unexplored
// pockets inside rooms are islands just like furniture. The map's outline is
// never furniture: the pieces holding an 8-connected obstacle region that
// touches the image border, or one with more cells than any piece under the
// perimeter limit can hold (a region's cells always share their fate). Of
// those outline regions only the cells next to free space enter the alpha
// shape, which is all that can join them to a nearby piece; other regions
// enter in full, so that a solid block's shape has no hole. With
// `wall_pieces` (null: the paper's step), the regions of furniture pieces
// that are pieces of wall (WallPieceSizes) stay; the rest of their piece
// goes.
FurnitureRemoval RemoveFurniture(std::string& cells, int width, int height, double alpha_radius_px,
                                 double max_perimeter_px, const WallPieceSizes* wall_pieces);

// The most cells an 8-connected obstacle region inside a furniture piece can
// have: lattice points in a shape with boundary length P number at most about
// P^2 / (4 pi) + P (area plus boundary), doubled for safety. Without bound
// (infinity) when alpha_radius_px < 1, where diagonal neighbours need not join.
double MaxFurnitureRegionCells(double alpha_radius_px, double max_perimeter_px);

}  // namespace areagraph

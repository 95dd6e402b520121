#pragma once

#include <cstdint>
#include <opencv2/core.hpp>
#include <string>
#include <vector>

#include "proto/geometry.pb.h"

namespace areagraph {

// What furniture removal took out of the grid.
struct FurnitureRemoval {
  // Flat cell indices, increasing.
  std::vector<int> removed_cells;
  // One convex outline (around the cells' squares, pixel coordinates) per
  // removed piece, for drawing.
  std::vector<proto::Polygon> shapes;
};

// What makes an obstacle region of a furniture piece a piece of wall
// standing between two doors (clean.keep_wall_pieces), in pixels: it is
// thinner than `thinner_than_px` (twice its deepest cell's depth), at least
// kWallPieceMinElongation times as long as wide and `min_length_px` long, and
// past both of its ends its line (the centre line of its smallest enclosing
// rectangle, or a line one cell beside it) meets another obstacle region
// within `max_gap_px`. A wall broken by two doors leaves such a piece; its
// perimeter is as short as a desk's.
struct WallPieceSizes {
  double thinner_than_px = 0;
  double min_length_px = 0;
  double max_gap_px = 0;
  // Thicker ridges are not walls when the typical wall is measured
  // (kMaxWallThicknessM).
  double max_wall_px = 0;
};
// Thinner than the least furniture island of ag-merge (0.3 m, and twice the
// map's typical wall, stages/merge/furniture_gap_joining.h): desks, cabinets
// and shelves are not.
inline constexpr double kWallPieceThinnerThanM = 0.3;
inline constexpr double kWallPieceWallRatio = 2.0;
inline constexpr double kWallPieceMinElongation = 3.0;
// At least as long as the short wall pieces that ag-cut takes as jambs
// (cut.close_wall_gaps_short_tips).
inline constexpr double kWallPieceMinLengthM = 0.5;
// The gap past each end is at most a door's (as kWallGapM,
// stages/cut/structure_sites.h).
inline constexpr double kWallPieceMaxGapM = 1.6;

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

// The obstacle regions (8-connected non-free cells of `cells`: `labels`, as
// cv::connectedComponents labels ObstacleMask, `label_count` of them) among
// those holding `candidate_cells` that are pieces of wall by `sizes`: 1 per
// label.
std::vector<uint8_t> WallPieceRegions(const std::string& cells, int width, int height,
                                      const cv::Mat& labels, int label_count,
                                      const std::vector<int>& candidate_cells,
                                      const WallPieceSizes& sizes);

// The most cells an 8-connected obstacle region inside a furniture piece can
// have: lattice points in a shape with boundary length P number at most about
// P^2 / (4 pi) + P (area plus boundary), doubled for safety. Without bound
// (infinity) when alpha_radius_px < 1, where diagonal neighbours need not join.
double MaxFurnitureRegionCells(double alpha_radius_px, double max_perimeter_px);

}  // namespace areagraph

#pragma once

#include <cstdint>
#include <opencv2/core.hpp>
#include <string>
#include <vector>

namespace areagraph {

// What makes an obstacle region of a furniture piece a piece of wall
// standing between two doors (clean pass KEEP_WALL_PIECES), in pixels: it is
// thinner than `thinner_than_px` or kFurnitureWallRatio times the map's
// typical wall (TypicalWallThickness; twice its deepest cell's depth), at
// least kWallPieceElongation (stages/geometry/furniture_shape.h) times as long
// as wide and `min_length_px` (kMinWallPieceM) long, and past both of its
// ends its line (the centre line of its smallest enclosing rectangle, or a
// line one cell beside it) meets another obstacle region within `max_gap_px`
// (kWallPieceGapM). A wall broken by two doors leaves such a piece; its
// perimeter is as short as a desk's.
struct WallPieceSizes {
  double thinner_than_px = 0;
  double min_length_px = 0;
  double max_gap_px = 0;
  // Thicker ridges are not walls when the typical wall is measured
  // (kMaxWallThicknessM).
  double max_wall_px = 0;
};
// A wall piece is thinner than furniture (kMinFurnitureThicknessM and
// kFurnitureWallRatio times the map's typical wall,
// stages/geometry/wall_thickness.h), as ag-merge's furniture islands are
// thicker.

// The obstacle regions (8-connected non-free cells of `cells`: `labels`, as
// cv::connectedComponents labels ObstacleMask, `label_count` of them) among
// those holding `candidate_cells` (flat indices, row-major; the rectangles
// are fitted to them) that are pieces of wall by `sizes`: 1 per label.
//
// The same result as measuring every region on the whole map's depth
// (DescribeObstacleRegions, TypicalWallThickness), but the depth is only
// measured where a decision needs it: a region's own depth once its shape
// and ends pass (within its box, where the map's transform is exact:
// ComputedExactly), and the map's typical wall only for a region not
// thinner than `thinner_than_px`.
std::vector<uint8_t> WallPieceRegions(const std::string& cells, int width, int height,
                                      const cv::Mat& labels, int label_count,
                                      const std::vector<int>& candidate_cells,
                                      const WallPieceSizes& sizes);

}  // namespace areagraph

#pragma once

#include <cstdint>
#include <vector>

namespace areagraph {

// The furniture pieces of RemoveFurniture's alpha shape. The points are the
// cells `point_cells` (flat indices, row-major order) of a width x height
// grid; `label` gives each cell's obstacle region and `outline` each
// region's outline flag. A piece is the points of alpha-shape components
// (disk radius alpha_radius_px) joined through shared regions; it is
// furniture when none of its regions is outline and its perimeter (the sum
// of its components' ComponentPerimeters) is below max_perimeter_px.
struct FurniturePieces {
  // Per point its furniture piece, or -1; pieces numbered by first point.
  std::vector<int> piece_of_point;
  int count = 0;
};

// From one triangulation of all the points: the definition.
FurniturePieces FurniturePiecesOfWholeShape(const std::vector<int>& point_cells, int width,
                                            const int* label, const std::vector<uint8_t>& outline,
                                            double alpha_radius_px, double max_perimeter_px);

// The same pieces from the clusters of points closer than the disk's
// diameter, each triangulated alone (in parallel when there are enough
// points); clusters whose every component must hold an outline point are
// not triangulated at all. Returns false (and leaves `pieces` unset) when it
// cannot tell that the answer is the whole shape's: a disk radius below 1,
// or a perimeter so close to max_perimeter_px that the order of its floating
// sum could decide the comparison.
bool FurniturePiecesByClusters(const std::vector<int>& point_cells, int width, int height,
                               const int* label, const std::vector<uint8_t>& outline,
                               double alpha_radius_px, double max_perimeter_px,
                               FurniturePieces* pieces);

}  // namespace areagraph

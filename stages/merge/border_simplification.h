#pragma once

#include <vector>

#include "stages/geometry/edge_polygon.h"

namespace areagraph {

// Simplifies all `chains` together (CGAL Polyline_simplification_2 on one
// constrained triangulation): vertices are dropped, never moved, while every
// dropped vertex of chain i stays within `tolerance_px[i]` of the segment
// that replaces it and no two chains come to touch or cross. The first and
// last point of every chain are kept, so chains that share an end still
// share it. The chains must meet only at their ends. Returns the chains'
// remaining points, in the same order; chains with tolerance 0 keep all.
std::vector<PointList> SimplifyBorders(const std::vector<PointList>& chains,
                                       const std::vector<double>& tolerance_px);

}  // namespace areagraph

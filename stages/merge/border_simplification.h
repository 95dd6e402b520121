#pragma once

#include <vector>

#include "stages/geometry/edge_polygon.h"

namespace areagraph {

// Simplifies all `chains` together (CGAL Polyline_simplification_2 on one
// constrained triangulation): vertices are dropped, never moved, while every
// dropped vertex stays within `tolerance_px` of the segment that replaces it
// and no two chains come to touch or cross. The first and last point of every
// chain are kept, so chains that share an end still share it. The chains
// must meet only at their ends. Returns the chains' remaining points, in the
// same order; `tolerance_px` 0 returns the chains unchanged.
std::vector<PointList> SimplifyBorders(const std::vector<PointList>& chains, double tolerance_px);

}  // namespace areagraph

#pragma once

#include <vector>

#include "stages/geometry/edge_polygon.h"

namespace areagraph {

// True when every ring has at least three points and no two segments of any
// rings touch or cross, except consecutive segments of one ring at their
// shared point (and those do not fold back onto each other). This is what
// makes an outer ring plus holes a valid polygon.
bool RingsAreSimple(const std::vector<PointList>& rings);

// Signed area by the shoelace formula; positive for rings that run
// clockwise on screen (pixel coordinates, y down).
double SignedArea(const PointList& ring);

}  // namespace areagraph

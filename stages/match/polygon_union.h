#pragma once

#include "proto/geometry.pb.h"

namespace areagraph {

// The union of two polygons that tile the plane together with others and
// share part of their border vertex for vertex, as ag-merge's areas do: the
// edges both hold (run in opposite directions, so the two outer rings have
// the same orientation) cancel, and the remaining edges chain into rings.
// Rings oriented like `a`'s outer ring are outer rings, the others holes.
// Returns false, leaving `out` alone, when the polygons share no edge or the
// result is not one outer ring with holes (they only touch at points, or
// their shared border does not match vertex for vertex).
bool UnionOfNeighbours(const proto::Polygon& a, const proto::Polygon& b, proto::Polygon* out);

}  // namespace areagraph

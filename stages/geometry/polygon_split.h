#pragma once

#include "proto/geometry.pb.h"

namespace areagraph {

// Cuts `whole` in two along the border of `guide`: `inside` is the largest
// connected piece of whole ∩ guide, `rest` is whole without it. Exact
// arithmetic (CGAL's Boolean set operations), rounded to doubles once, so
// the two pieces share their cut vertex for vertex. The pieces' outer rings
// run like `whole`'s, their holes the other way. Returns false, leaving both
// alone, when a ring is not simple, the pieces are not one polygon (with
// holes) each, or one of them is empty. ag-match undoes a join of two areas
// with it (stages/match/join_undoing.h).
bool SplitPolygonByGuide(const proto::Polygon& whole, const proto::Polygon& guide,
                         proto::Polygon* inside, proto::Polygon* rest);

}  // namespace areagraph

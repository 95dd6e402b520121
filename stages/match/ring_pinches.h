#pragma once

#include "proto/geometry.pb.h"

namespace areagraph {

// `polygon` with each ring that passes through one vertex twice (a pinch,
// which CGAL's Boolean operations refuse as not simple) replaced by its
// largest loop: the ring is cut into loops at its repeated vertices and the
// loop with the largest area stays. Rings without repeats stay as they are.
// Join undoing cuts a joined area along a previous area's border with it
// (stages/match/join_undoing.h); on a noisy scan a previous corridor whose outline
// touched itself at one vertex (a one-vertex pinch off a 6-vertex lobe) kept
// its join for good, since every cut along it was refused.
proto::Polygon WithoutPinches(const proto::Polygon& polygon);

}  // namespace areagraph

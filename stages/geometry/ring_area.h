#pragma once

#include "proto/geometry.pb.h"

namespace areagraph {

// Twice the signed area of a ring (shoelace): positive when the ring runs
// counter-clockwise in a y-up frame such as world metres (clockwise on
// screen, in pixels). The one shoelace for proto rings.
double TwiceSignedArea(const proto::Ring& ring);

}  // namespace areagraph

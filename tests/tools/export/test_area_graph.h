#pragma once

#include "proto/artifacts.pb.h"

namespace areagraph::testing {

// A 40x20 px map at 0.05 m/px with two 10x10 px square areas side by side and
// one passage through their shared edge:
// - area 0 (room): pixels x 2..12, y 2..12 -> 100 px;
// - area 1 (corridor): x 12..22, y 2..12 with a 2x2 px hole at x 16..18,
//   y 6..8 -> 96 px;
// - passage 0 from area 0 to area 1 along x = 12 px, y 4..10 px (0.3 m).
// polygon_m is polygon_px through the map frame (origin 1 m, 2 m).
proto::AreaGraph TwoRoomAreaGraph();

}  // namespace areagraph::testing

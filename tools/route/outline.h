#pragma once

#include <Eigen/Core>
#include <vector>

namespace areagraph {

using Vec2 = Eigen::Vector2d;

// Distances below this (metres) count as zero: the areas share their border
// vertices bit for bit, so only rounding in the tests needs it.
constexpr double kRouteTolerance = 1e-7;

// One edge of an area's outline. A wall unless it lies on a passage's border
// (passage.border_m) and on both areas' outlines: two areas that touch
// elsewhere are apart.
struct OutlineEdge {
  Vec2 a, b;
  int area = 0;                    // index into AreaGraph.areas
  int vertex_a = 0, vertex_b = 0;  // indices into FreeSpace::vertices()
  bool wall = true;
};

// One corner of an area's outline, where the area's inside spans the angle
// from the direction of `next` counter-clockwise to that of `previous`.
struct CornerWedge {
  int area = 0;
  int next = 0, previous = 0;  // vertex indices
  double angle = 0;            // radians, in (0, 2 pi]
  bool next_is_wall = true, previous_is_wall = true;
};

// A point where outline edges meet, with what meets there.
struct OutlineVertex {
  Vec2 at;
  std::vector<Vec2> wall_directions;  // towards the other end of each wall from here
  std::vector<CornerWedge> wedges;
};

}  // namespace areagraph

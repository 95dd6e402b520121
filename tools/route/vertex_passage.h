#pragma once

#include <vector>

#include "tools/route/outline.h"

namespace areagraph {

// How a straight line through an outline vertex meets the walls there.
struct VertexPassage {
  // A wall runs along the line before the vertex, and after it.
  bool behind = false, ahead = false;
  // Off the walls' lines: walls on both sides, so the line crosses one.
  bool crosses = false;
  // Along a wall: the line's sides (kLeftBank, kRightBank) that no wall
  // leaves from the vertex and that an area fills, where the line may go on.
  int banks = 0;
};
constexpr int kLeftBank = 1;
constexpr int kRightBank = 2;

// The line along `unit` (a unit vector) through `vertex` of `vertices`.
VertexPassage PassThrough(const std::vector<OutlineVertex>& vertices, const OutlineVertex& vertex,
                          const Vec2& unit);

// A stretch of free space around an outline vertex: from one wall
// counter-clockwise through the wedges of the areas that meet there (across
// passage borders) to the next wall.
struct FreeStretch {
  double angle = 0;  // radians; 2 pi where no wall meets the vertex
  bool walled = true;
  Vec2 from_wall, to_wall;  // unit directions of the walls that bound it
  std::vector<int> areas;   // sorted
  std::vector<int> rays;    // the vertices that its passage borders run to
};

// The stretches around `vertex`.
std::vector<FreeStretch> FreeStretches(const std::vector<OutlineVertex>& vertices,
                                       const OutlineVertex& vertex);

// Whether `direction` from `vertex` points into one of its wedges (strictly).
bool WedgeHolds(const std::vector<OutlineVertex>& vertices, const OutlineVertex& vertex,
                const Vec2& direction);

}  // namespace areagraph

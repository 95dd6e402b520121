#include "stages/merge/one_sided_narrowing.h"

#include <cmath>

#include "stages/geometry/wall_thickness.h"

namespace areagraph {
namespace {

// Whether the obstacle cell at `side` is part of a flat wall face that runs
// across the line toward `other` (the narrowing's other side) for the
// narrowing's width both ways.
bool FlatWallAt(const CellGrid& grid, const Eigen::Vector2d& side, const Eigen::Vector2d& other) {
  const Eigen::Vector2d toward = other - side;
  const double width = toward.norm();
  if (width < 1) return false;
  const Eigen::Vector2d u = toward / width;  // into the opening
  const Eigen::Vector2d t(-u.y(), u.x());    // along the face
  const int reach = static_cast<int>(std::ceil(width));
  int face = 0, samples = 0;
  for (int s = -reach; s <= reach; ++s) {
    const Eigen::Vector2d p = side + s * t;
    // The wall: an obstacle cell within a cell and a half behind the face
    // line (the site is the nearest obstacle cell; the face may be slanted).
    bool wall = false;
    for (const double k : {-1.5, -1.0, -0.5, 0.0, 0.5}) wall = wall || !grid.FreeAt(p + k * u);
    // In front of it: free cells.
    bool open = true;
    for (const double k : {1.5, 2.0, 2.5}) open = open && grid.FreeAt(p + k * u);
    ++samples;
    if (wall && open) ++face;
  }
  return face >= (1 - kMissedWallShare) * samples;
}

}  // namespace

bool OneSidedNarrowing(const CellGrid& grid, const Eigen::Vector2d& left,
                       const Eigen::Vector2d& right) {
  return FlatWallAt(grid, left, right) || FlatWallAt(grid, right, left);
}

}  // namespace areagraph

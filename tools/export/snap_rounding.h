#pragma once

#include <cstdint>
#include <map>
#include <set>
#include <utility>
#include <vector>

namespace areagraph {

// A point of the integer grid that positions are rounded onto.
using GridPoint = std::pair<int64_t, int64_t>;

// A position in grid units, before rounding.
struct GridPosition {
  double x = 0;
  double y = 0;
};

// Snap rounding (Hobby's) onto the integer grid: every vertex goes to its
// nearest grid point, and every edge is routed through the grid point of each
// hot pixel (the unit square around a vertex's grid point) that the original
// edge passes through, in order along the edge. Rounding vertices alone can
// move one across a nearby edge and make a simple ring cross itself; routed
// this way no two output edges cross, though a ring may touch itself where a
// neck was narrower than the grid (a grid point visited twice) and
// consecutive repeats may appear. An edge that two rings share is routed
// alike in both.
class SnapRounder {
 public:
  // The hot pixels: those of every vertex of `rings`.
  explicit SnapRounder(const std::vector<std::vector<GridPosition>>& rings);

  // A closed ring (first vertex not repeated at the end), and an open line.
  std::vector<GridPoint> Ring(const std::vector<GridPosition>& ring) const;
  std::vector<GridPoint> Line(const std::vector<GridPosition>& line) const;

 private:
  // The hot pixels that the edge a -> b passes through besides its own ends',
  // in order along it.
  std::vector<GridPoint> Along(const GridPosition& a, const GridPosition& b) const;

  std::map<GridPoint, std::set<GridPoint>> buckets_;
};

}  // namespace areagraph

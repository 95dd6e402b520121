#pragma once

#include <cstdint>
#include <vector>

#include "proto/artifacts.pb.h"

namespace areagraph {

// Shortest 8-connected paths through the free cells of a grid map: a step to
// one of the 8 neighbours (diagonals too, even past a corner) costs its
// length, one cell or the square root of two, times the resolution. What
// routes are measured against (tools/bench-route.sh).
// Variants of the grid paths (the default is none of them).
struct GridPathRules {
  // Cells nearer than this to an occupied or unknown cell are not free.
  double clearance_m = 0;
  // A diagonal step needs both cells beside it free.
  bool no_corner_cutting = false;
};

class GridGeodesic {
 public:
  explicit GridGeodesic(const proto::GridMap& grid, const GridPathRules& rules = {});

  int width() const { return width_; }
  int height() const { return height_; }
  bool Free(int cell) const { return free_[cell] != 0; }
  // The 8-connected part of the free cells that `cell` belongs to (-1 for
  // an occupied or unknown cell).
  int Component(int cell) const { return component_[cell]; }

  // The length in metres of the shortest path between two free cells
  // (centre to centre), or infinity. With `estimate`, A* with the octile
  // distance; without, Dijkstra's algorithm stopping at `to`.
  double Length(int from, int to, bool estimate);

 private:
  int width_ = 0, height_ = 0;
  double resolution_m_ = 0;
  bool no_corner_cutting_ = false;
  std::vector<uint8_t> free_;
  std::vector<int> component_;
  // The free cell one step (dx, dy) from `cell` under the rules, or -1.
  int StepFrom(int cell, int dx, int dy) const;
  // Scratch for Length, valid where stamp_ is the current search's.
  std::vector<double> best_;
  std::vector<uint32_t> stamp_;
  uint32_t search_ = 0;
};

}  // namespace areagraph

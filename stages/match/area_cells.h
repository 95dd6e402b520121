#pragma once

#include <cstdint>
#include <vector>

#include "proto/artifacts.pb.h"
#include "proto/geometry.pb.h"

namespace areagraph {

// A run of cells [x0, x1) in one row that belong to area `area` (its index
// in the graph).
struct CellRun {
  int x0 = 0;
  int x1 = 0;
  int area = 0;
};

// The cells of every area of a graph on the grid of some frame, as runs per
// row: what matching and diffs compare, so that they count cells and do not
// depend on how the outlines are drawn (pixel staircases or simplified
// borders give nearly the same cells).
struct AreaCells {
  int width = 0;
  int height = 0;
  double resolution_m = 0;
  // rows[r]: the runs of row r, sorted and disjoint (where two polygons
  // overlap, the cells go to the run that starts first).
  std::vector<std::vector<CellRun>> rows;
  // Cells of each area inside the frame.
  std::vector<int64_t> cells;
};

// Rasterizes the areas of `graph` (their polygons in metres) onto the grid of
// `frame`: a cell belongs to an area when its centre lies inside the outer
// ring and outside the holes (even-odd rule, half-open edges, so polygons
// that tile the plane give every cell to one area). Cells outside the frame
// are left out.
AreaCells RasterizeAreas(const proto::AreaGraph& graph, const proto::MapFrame& frame);

// How many cells two areas share, for areas of two graphs on one grid.
struct AreaOverlap {
  int before = 0;  // area index in the first graph
  int after = 0;   // area index in the second graph
  int64_t cells = 0;
};

// Every pair of areas with shared cells, ordered by (before, after). Both
// must be rasterized on the same frame.
std::vector<AreaOverlap> CountOverlaps(const AreaCells& before, const AreaCells& after);

}  // namespace areagraph

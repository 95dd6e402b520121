#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace areagraph {

// A run of cells in one row: columns [begin, end) of `row`.
struct CellRun {
  int row;
  int begin;
  int end;
};

// The runs of a CellState grid's cells that have `bit` set (CELL_UNKNOWN:
// 2; non-free: 3), in row-major order, and their 8-connected regions: per
// run its region, numbered 0 .. count - 1 in the order of their first runs.
// Found over the runs instead of cell by cell: a map is mostly long runs.
struct RunRegions {
  std::vector<CellRun> runs;
  std::vector<int> region;
  int count = 0;
};
RunRegions FindRunRegions(const std::string& cells, int width, int height, uint8_t bit);

// Whether a run lies on the image border.
inline bool OnBorder(const CellRun& run, int width, int height) {
  return run.row == 0 || run.row == height - 1 || run.begin == 0 || run.end == width;
}

}  // namespace areagraph

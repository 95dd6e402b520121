#include "stages/clean/unknown_islands.h"

#include <algorithm>
#include <cstdint>

#include "proto/artifacts.pb.h"
#include "stages/clean/mask_runs.h"
#include "stages/geometry/disjoint_sets.h"

namespace areagraph {
namespace {

// A run of unknown cells: columns [begin, end) of `row`.
struct Run {
  int row;
  int begin;
  int end;
};

}  // namespace

std::vector<int> FreeUnknownIslands(std::string& cells, int width, int height, double max_cells) {
  std::vector<int> freed;
  if (max_cells <= 0) return freed;
  // The unknown cells' runs, row by row (no per-cell labels: a map's unknown
  // space is mostly long runs), and where each row's runs start.
  static_assert(proto::CELL_UNKNOWN == 2 && proto::CELL_FREE == 0 && proto::CELL_OCCUPIED == 1);
  const auto* state = reinterpret_cast<const uint8_t*>(cells.data());
  std::vector<Run> runs;
  std::vector<size_t> row_start(size_t(height) + 1, 0);
  for (int r = 0; r < height; ++r) {
    row_start[r] = runs.size();
    ForEachRun(state + size_t(r) * width, width, proto::CELL_UNKNOWN, [&](int begin, int end) {
      runs.push_back({r, begin, end});
    });
  }
  row_start[height] = runs.size();
  // 8-connected regions: runs of neighbouring rows that overlap or touch
  // diagonally. Both rows' runs are in column order: one sweep.
  DisjointSets regions(runs.size());
  for (int r = 1; r < height; ++r) {
    size_t above = row_start[r - 1];
    for (size_t i = row_start[r]; i < row_start[r + 1]; ++i) {
      while (above < row_start[r] && runs[above].end < runs[i].begin) ++above;
      for (size_t a = above; a < row_start[r] && runs[a].begin <= runs[i].end; ++a) {
        regions.Union(int(a), int(i));
      }
    }
  }
  // Per region (by its root): cells, and whether it touches the border.
  std::vector<int64_t> area(runs.size(), 0);
  std::vector<uint8_t> on_border(runs.size(), 0);
  std::vector<int> root(runs.size());
  for (size_t i = 0; i < runs.size(); ++i) {
    const Run& run = runs[i];
    root[i] = regions.Find(int(i));
    area[root[i]] += run.end - run.begin;
    on_border[root[i]] |=
        run.row == 0 || run.row == height - 1 || run.begin == 0 || run.end == width;
  }
  // The islands' runs are in row-major order: so are their cells.
  for (size_t i = 0; i < runs.size(); ++i) {
    if (on_border[root[i]] || double(area[root[i]]) > max_cells) continue;
    for (int c = runs[i].begin; c < runs[i].end; ++c) {
      freed.push_back(runs[i].row * width + c);
      cells[size_t(runs[i].row) * width + c] = proto::CELL_FREE;
    }
  }
  return freed;
}

}  // namespace areagraph

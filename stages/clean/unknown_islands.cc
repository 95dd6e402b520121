#include "stages/clean/unknown_islands.h"

#include <cstdint>

#include "proto/artifacts.pb.h"
#include "stages/clean/cell_runs.h"

namespace areagraph {

std::vector<int> FreeUnknownIslands(std::string& cells, int width, int height, double max_cells) {
  std::vector<int> freed;
  if (max_cells <= 0) return freed;
  static_assert(proto::CELL_UNKNOWN == 2 && proto::CELL_FREE == 0 && proto::CELL_OCCUPIED == 1);
  // The unknown cells' runs and regions: no mask, no per-cell labels.
  const RunRegions unknown = FindRunRegions(cells, width, height, proto::CELL_UNKNOWN);
  std::vector<int64_t> area(unknown.count, 0);
  std::vector<uint8_t> on_border(unknown.count, 0);
  for (size_t i = 0; i < unknown.runs.size(); ++i) {
    const CellRun& run = unknown.runs[i];
    area[unknown.region[i]] += run.end - run.begin;
    on_border[unknown.region[i]] |= OnBorder(run, width, height);
  }
  // The islands' runs are in row-major order: so are their cells.
  for (size_t i = 0; i < unknown.runs.size(); ++i) {
    const int region = unknown.region[i];
    if (on_border[region] || double(area[region]) > max_cells) continue;
    const CellRun& run = unknown.runs[i];
    for (int c = run.begin; c < run.end; ++c) {
      freed.push_back(run.row * width + c);
      cells[size_t(run.row) * width + c] = proto::CELL_FREE;
    }
  }
  return freed;
}

}  // namespace areagraph

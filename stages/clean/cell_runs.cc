#include "stages/clean/cell_runs.h"

#include "stages/clean/mask_runs.h"
#include "stages/geometry/region_boxes.h"

namespace areagraph {

RunRegions FindRunRegions(const std::string& cells, int width, int height, uint8_t bit) {
  RunRegions found;
  std::vector<CellRun>& runs = found.runs;
  const auto* state = reinterpret_cast<const uint8_t*>(cells.data());
  // Where each row's runs start in `runs` (one more entry for the end).
  std::vector<size_t> row_start(size_t(height) + 1, 0);
  for (int r = 0; r < height; ++r) {
    row_start[r] = runs.size();
    ForEachRun(state + size_t(r) * width, width, bit, [&](int begin, int end) {
      runs.push_back({r, begin, end});
    });
  }
  row_start[height] = runs.size();
  // Runs of neighbouring rows join when they overlap or touch diagonally.
  found.region = JoinRowRuns(
      runs, row_start, /*eight_connected=*/true,
      [](const CellRun&, const CellRun&) { return true; }, &found.count);
  return found;
}

}  // namespace areagraph

#include "stages/clean/cell_runs.h"

#include <algorithm>

#include "stages/clean/mask_runs.h"
#include "stages/geometry/parallel_ranges.h"
#include "stages/geometry/region_boxes.h"

namespace areagraph {

RunRegions FindRunRegions(const std::string& cells, int width, int height, uint8_t bit) {
  RunRegions found;
  std::vector<CellRun>& runs = found.runs;
  const auto* state = reinterpret_cast<const uint8_t*>(cells.data());
  // The rows' runs in bands of rows on the pool (a band at least 256 Ki
  // cells), joined in band order: row-major as one pass finds them.
  const size_t min_rows = std::max<size_t>(1, (size_t{1} << 18) / size_t(std::max(width, 1)));
  runs = ConcatRanges<CellRun>(size_t(height), min_rows, [&](size_t begin, size_t end) {
    std::vector<CellRun> band;
    for (int r = int(begin); r < int(end); ++r) {
      ForEachRun(state + size_t(r) * width, width, bit, [&](int first, int last) {
        band.push_back({r, first, last});
      });
    }
    return band;
  });
  // Where each row's runs start in `runs` (one more entry for the end).
  std::vector<size_t> row_start(size_t(height) + 1, 0);
  for (const CellRun& run : runs) ++row_start[size_t(run.row) + 1];
  for (int r = 0; r < height; ++r) row_start[r + 1] += row_start[r];
  // Runs of neighbouring rows join when they overlap or touch diagonally.
  found.region = JoinRowRuns(
      runs, row_start, /*eight_connected=*/true,
      [](const CellRun&, const CellRun&) { return true; }, &found.count);
  return found;
}

}  // namespace areagraph

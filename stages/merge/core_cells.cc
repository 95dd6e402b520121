#include "stages/merge/core_cells.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <vector>

#include "stages/geometry/distance_transform.h"
#include "stages/geometry/parallel_ranges.h"

namespace areagraph {
namespace {

// At least this many cells per parallel range of rows: a smaller range
// costs more to start than it gains.
constexpr size_t kMinRangeCells = size_t(1) << 16;
// Beyond this many cells of reach the capped column distances would not fit a byte.
constexpr int kMaxNearer = 250;

// The least squared integer distance d whose distance value,
// sqrt(float(d)) as the exact transform rounds it, reaches `reach` (> 0).
int64_t SquaredReach(float reach) {
  int64_t d = static_cast<int64_t>(std::ceil(double(reach) * double(reach)));
  while (d > 0 && std::sqrt(float(d - 1)) >= reach) --d;
  while (std::sqrt(float(d)) < reach) ++d;
  return d;
}

// DistanceAtLeast on the free cells, then the domain: any size, any reach.
cv::Mat WholeMapCores(const CellGrid& grid, const cv::Mat& domain, float reach) {
  // The sizes in locals: a byte stored through a row could alias the Mat's
  // own fields, so a loop bound read from them is reloaded every cell and
  // the loop stays scalar (a 50-megapixel map: 400 M instructions).
  const int rows = domain.rows, cols = domain.cols;
  cv::Mat cells(rows, cols, CV_8U);
  for (int r = 0; r < rows; ++r) {
    uint8_t* __restrict row = cells.ptr<uint8_t>(r);
    const uint8_t* __restrict state = grid.CellRow(r);
    for (int c = 0; c < cols; ++c) row[c] = state[c] == proto::CELL_FREE ? 255 : 0;
  }
  cv::Mat core = DistanceAtLeast(cells, reach);
  cells.release();
  for (int r = 0; r < rows; ++r) {
    uint8_t* __restrict row = core.ptr<uint8_t>(r);
    const uint8_t* __restrict inside = domain.ptr<uint8_t>(r);
    for (int c = 0; c < cols; ++c) row[c] = (row[c] != 0) & (inside[c] != 0);
  }
  return core;
}

// One row of CoreCells: `v` its capped column distances, `inside` its domain.
// Plain arguments: in a lambda, every byte stored would reload the captures.
void CoreRow(const uint8_t* v, const uint8_t* __restrict inside, uint8_t* out, int cols, int nearer,
             const int* spread, uint64_t far_word) {
  // From the left: cells that a column at or before them keeps short.
  int kept_until = -1;
  for (int q = 0; q < cols;) {
    uint64_t eight = 1;
    if (q + 8 <= cols) std::memcpy(&eight, v + q, 8);
    if (eight == far_word && kept_until < q) {
      std::memset(out + q, 1, 8);
      q += 8;
      continue;
    }
    if (eight == 0) {
      kept_until = std::max(kept_until, q + 7 + spread[0]);
      std::memset(out + q, 0, 8);
      q += 8;
      continue;
    }
    if (v[q] < nearer) kept_until = std::max(kept_until, q + spread[v[q]]);
    out[q] = q > kept_until;
    ++q;
  }
  // From the right: a cell already kept short stays so.
  int kept_from = cols;
  for (int q = cols - 1; q >= 0;) {
    uint64_t eight = 1;
    if (q >= 7) std::memcpy(&eight, v + q - 7, 8);
    if (eight == far_word && kept_from > q) {
      q -= 8;
      continue;
    }
    if (eight == 0) {
      kept_from = std::min(kept_from, q - 7 - spread[0]);
      q -= 8;
      continue;
    }
    if (v[q] < nearer) kept_from = std::min(kept_from, q - spread[v[q]]);
    out[q] &= q < kept_from;
    --q;
  }
  for (int c = 0; c < cols; ++c) out[c] &= inside[c] != 0;
}

}  // namespace

cv::Mat CoreCells(const CellGrid& grid, const cv::Mat& domain, double min_gap_px) {
  const int rows = grid.height(), cols = grid.width();
  CV_Assert(domain.type() == CV_8U && domain.rows == rows && domain.cols == cols);
  const float reach = static_cast<float>(0.5 * min_gap_px);
  if (rows == 0 || cols == 0 || !(reach > 0) || !ComputedExactly(cv::Size(cols, rows))) {
    return WholeMapCores(grid, domain, reach);
  }
  // A column whose nearest obstacle is v < nearer cells away keeps the cells
  // of its row within spread[v] of it short of the reach.
  const int64_t k = SquaredReach(reach);
  std::vector<int> spread;
  for (int64_t v = 0; v * v < k && v <= kMaxNearer; ++v) {
    int64_t t = 0;
    while ((t + 1) * (t + 1) < k - v * v) ++t;
    spread.push_back(static_cast<int>(t));
  }
  const int nearer = static_cast<int>(spread.size());
  if (nearer > kMaxNearer) return WholeMapCores(grid, domain, reach);
  // Column distances to the nearest non-free cell, counted up to `nearer`.
  const uint8_t cap = static_cast<uint8_t>(nearer);
  // Without a non-free cell the transform is OpenCV's, not the exact one
  // (most maps' first row already has one).
  bool any_obstacle = false;
  for (int r = 0; r < rows && !any_obstacle; ++r) {
    const uint8_t* state = grid.CellRow(r);
    any_obstacle =
        std::any_of(state, state + cols, [](uint8_t s) { return s != proto::CELL_FREE; });
  }
  if (!any_obstacle) return WholeMapCores(grid, domain, reach);
  std::vector<uint8_t> column(static_cast<size_t>(rows) * cols);
  std::vector<uint8_t> none(cols, cap - 1);
  for (int r = 0; r < rows; ++r) {
    const uint8_t* __restrict state = grid.CellRow(r);
    uint8_t* __restrict out = column.data() + static_cast<size_t>(r) * cols;
    // Above the first row no column has an obstacle.
    const uint8_t* __restrict above = r > 0 ? out - cols : none.data();
    // Byte arithmetic without a branch, which the compiler vectorises.
    for (int c = 0; c < cols; ++c) {
      uint8_t d = static_cast<uint8_t>(above[c] + 1);
      d = d < cap ? d : cap;
      const uint8_t free = static_cast<uint8_t>(-(state[c] == proto::CELL_FREE));
      out[c] = d & free;
    }
  }
  for (int r = rows - 2; r >= 0; --r) {
    uint8_t* __restrict out = column.data() + static_cast<size_t>(r) * cols;
    const uint8_t* __restrict below = out + cols;
    for (int c = 0; c < cols; ++c) {
      const uint8_t d = static_cast<uint8_t>(below[c] + 1);
      out[c] = out[c] < d ? out[c] : d;
    }
  }
  cv::Mat core(rows, cols, CV_8U);
  const uint64_t far_word = 0x0101010101010101ull * cap;
  // Each row on its own: ranges of rows in parallel.
  const size_t min_rows = std::max<size_t>(8, kMinRangeCells / static_cast<size_t>(cols));
  // The lambda takes pointers, not the vectors: a vector whose address
  // escapes is reloaded after every byte stored, in the passes above too.
  const uint8_t* distances = column.data();
  const int* spreads = spread.data();
  ForEachRange(rows, ParallelRangeCount(rows, min_rows),
               [=, &domain, &core](size_t begin, size_t end, int) {
                 for (int r = static_cast<int>(begin); r < static_cast<int>(end); ++r) {
                   CoreRow(distances + static_cast<size_t>(r) * cols, domain.ptr<uint8_t>(r),
                           core.ptr<uint8_t>(r), cols, nearer, spreads, far_word);
                 }
               });
  return core;
}

}  // namespace areagraph

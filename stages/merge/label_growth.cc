#include "stages/merge/label_growth.h"

#include <algorithm>
#include <cstdint>
#include <cstring>

namespace areagraph {
namespace {

// A cell of the growth's queue; it keeps its column, so that no cell's
// index is divided out.
struct Entry {
  int index;
  int col;
};

// Breadth-first growth of all labels into unlabelled domain
// cells from `front` (labelled cells, row-major), linear in the grid. The
// queue is held as two fronts, this step's and the next's, in the order a
// single queue would hold them: only the growing front is held, never the map.
void GrowFrom(std::vector<Entry> front, const cv::Mat& domain, cv::Mat* labels) {
  const int cols = labels->cols;
  const int64_t cells = static_cast<int64_t>(cols) * labels->rows;
  const uint8_t* inside = domain.ptr<uint8_t>();
  int* label = labels->ptr<int>();
  auto open = [&](int q) { return inside[q] && label[q] == 0; };
  std::vector<Entry> next;
  while (!front.empty()) {
    next.clear();
    for (const Entry& p : front) {
      const int grown = label[p.index];
      // The neighbours in the order +x, -x, +y, -y.
      auto take = [&](int q, int col) {
        if (!open(q)) return;
        label[q] = grown;
        next.push_back({q, col});
      };
      if (p.col + 1 < cols) take(p.index + 1, p.col + 1);
      if (p.col > 0) take(p.index - 1, p.col - 1);
      if (p.index + cols < cells) take(p.index + cols, p.col);
      if (p.index >= cols) take(p.index - cols, p.col);
    }
    front.swap(next);
  }
}

}  // namespace

// Only labelled cells beside an unlabelled domain cell are seeded (the others
// would add nothing when their turn came, since labels are only ever set).
void GrowLabels(const cv::Mat& domain, cv::Mat* labels) {
  CV_Assert(domain.isContinuous() && labels->isContinuous());
  const int cols = labels->cols, rows = labels->rows;
  const uint8_t* inside = domain.ptr<uint8_t>();
  const int* label = labels->ptr<int>();
  std::vector<Entry> front;
  // The open cells of three rows (above, this one, below) as bytes with a
  // closed cell at either end, so that the seed test runs over whole rows
  // without bounds checks and vectorises: nearly every cell is labelled
  // and only a few are seeds.
  const int padded = cols + 2;
  std::vector<uint8_t> open_rows(3 * static_cast<size_t>(padded), 0), seed(cols);
  uint8_t* above = open_rows.data();
  uint8_t* here = above + padded;
  uint8_t* below = here + padded;
  auto open_row = [&](int r, uint8_t* out) {
    if (r >= rows) {
      std::fill(out, out + padded, 0);
      return;
    }
    const uint8_t* in = inside + static_cast<size_t>(r) * cols;
    const int* row = label + static_cast<size_t>(r) * cols;
    for (int c = 0; c < cols; ++c) out[c + 1] = (in[c] != 0) & (row[c] == 0);
  };
  open_row(0, here);
  open_row(1, below);
  for (int r = 0; r < rows; ++r) {
    const int* row = label + static_cast<size_t>(r) * cols;
    for (int c = 0; c < cols; ++c) {
      seed[c] = (row[c] != 0) & (here[c] | here[c + 2] | above[c + 1] | below[c + 1]);
    }
    for (int c = 0; c < cols;) {
      uint64_t eight = 0;
      if (c + 8 <= cols) std::memcpy(&eight, &seed[c], 8);
      if (c + 8 <= cols && eight == 0) {
        c += 8;
        continue;
      }
      if (seed[c]) front.push_back({r * cols + c, c});
      ++c;
    }
    std::swap(above, here);
    std::swap(here, below);
    open_row(r + 2, below);
  }
  GrowFrom(std::move(front), domain, labels);
}

void GrowIntoCleared(const std::vector<PieceRun>& cleared, const cv::Mat& domain, cv::Mat* labels) {
  const int cols = labels->cols, rows = labels->rows;
  const int* label = labels->ptr<int>();
  std::vector<int> seeds;
  auto consider = [&](int r, int c) {
    const int index = r * cols + c;
    if (label[index] != 0) seeds.push_back(index);
  };
  for (const PieceRun& run : cleared) {
    if (run.begin > 0) consider(run.row, run.begin - 1);
    if (run.end < cols) consider(run.row, run.end);
    for (int c = run.begin; c < run.end; ++c) {
      if (run.row > 0) consider(run.row - 1, c);
      if (run.row + 1 < rows) consider(run.row + 1, c);
    }
  }
  std::sort(seeds.begin(), seeds.end());
  seeds.erase(std::unique(seeds.begin(), seeds.end()), seeds.end());
  std::vector<Entry> front;
  front.reserve(seeds.size());
  for (const int index : seeds) front.push_back({index, index % cols});
  GrowFrom(std::move(front), domain, labels);
}

}  // namespace areagraph

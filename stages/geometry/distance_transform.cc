#include "stages/geometry/distance_transform.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <memory>
#include <numeric>
#include <opencv2/imgproc.hpp>
#include <vector>

#include "stages/geometry/exact_distance_rows.h"
#include "stages/geometry/parallel_ranges.h"
#include "stages/geometry/parallel_zeros.h"
#include "stages/geometry/single_precision_distances.h"
#ifdef __SSE2__
#include <immintrin.h>
#endif

namespace areagraph {
namespace {

using namespace distance_rows;  // the parts of this file in their own headers

// The largest of n >= 1 finite floats, four at a time where SSE is.
float LargestOf(const float* x, int n) {
  float largest = x[0];
  int i = 0;
#ifdef __SSE2__
  if (n >= 4) {
    __m128 four = _mm_loadu_ps(x);
    for (i = 4; i + 4 <= n; i += 4) four = _mm_max_ps(four, _mm_loadu_ps(x + i));
    float lanes[4];
    _mm_storeu_ps(lanes, four);
    largest = std::max({lanes[0], lanes[1], lanes[2], lanes[3]});
  }
#endif
  for (; i < n; ++i) largest = std::max(largest, x[i]);
  return largest;
}

// deepest[label[c]] = max(deepest[label[c]], value[c]) along a row, one
// store per run of a label (the store-to-load chain cell by cell is slow).
void DeepestAlongRow(const int* label, const float* value, int n, float* deepest) {
  for (int c = 0; c < n;) {
    const int run_label = label[c];
    float largest = deepest[run_label];
    for (; c < n && label[c] == run_label; ++c) largest = std::max(largest, value[c]);
    deepest[run_label] = largest;
  }
}

// The least squared distance whose DistanceValue reaches `reach` (> 0).
int64_t SquaredReach(float reach) {
  int64_t k = int64_t(std::ceil(double(reach) * double(reach)));
  while (k > 0 && std::sqrt(float(k - 1)) >= reach) --k;
  while (std::sqrt(float(k)) < reach) ++k;
  return k;
}

// One row of DistanceAtLeast's exact path: `v` its column distances, a
// column `v` < `nearer` away from its zero cell keeping the cells within
// spread[v] of it short. Plain arguments: in a lambda, every byte stored
// would reload the captures.
void AtLeastRow(const uint16_t* v, uint8_t* out, int cols, int nearer, const int* spread) {
  // From the left: cells that a column at or before them keeps short.
  int kept_until = -1;
  for (int q = 0; q < cols; ++q) {
    if (v[q] < nearer) kept_until = std::max(kept_until, q + spread[v[q]]);
    out[q] = q > kept_until;
  }
  // From the right.
  int kept_from = cols;
  for (int q = cols - 1; q >= 0; --q) {
    if (v[q] < nearer) kept_from = std::min(kept_from, q - spread[v[q]]);
    out[q] &= q < kept_from;
  }
}

}  // namespace

bool ComputedExactly(cv::Size size) {
  // The guard of ColumnDistances with the farthest distance a column can have.
  const int64_t rows = size.height, cols = size.width;
  return (rows - 1) * (rows - 1) + (cols - 1) * (cols - 1) < (int64_t(1) << 24);
}

cv::Mat ExactDistanceTransform(const cv::Mat& mask) {
  CV_Assert(mask.type() == CV_8U);
  const std::vector<uint16_t> columns = ColumnDistances(mask);
  if (columns.empty()) return OpenCvDistances(mask);
  const int rows = mask.rows, cols = mask.cols;
  cv::Mat distance = ZerosInParallel(cv::Size(cols, rows), CV_32F);
  ForEachRowRange(rows, cols, [&](int begin, int end) {
    std::vector<int32_t> f(cols);
    LowerEnvelope envelope(cols);
    for (int r = begin; r < end; ++r) {
      SquareRow(columns.data() + size_t(r) * cols, cols, f.data());
      float* out = distance.ptr<float>(r);
      ForEachNonZeroCell(mask.ptr<uint8_t>(r), f.data(), cols, envelope,
                         [&](int q, int p) { out[q] = DistanceValue(f.data(), q, p); });
    }
  });
  return distance;
}

double DeepestDistance(const cv::Mat& mask) {
  CV_Assert(mask.type() == CV_8U);
  if (mask.empty()) return 0;
  const std::vector<uint16_t> columns = ColumnDistances(mask);
  if (columns.empty()) {
    if (!FitsIntegers(mask)) {
      double deepest = 0;
      cv::minMaxLoc(OpenCvDistances(mask), nullptr, &deepest);
      return deepest;
    }
    // Each range's maximum, then theirs (maxima do not depend on the order).
    const SinglePrecisionTables tables(mask.rows, mask.cols);
    std::vector<float> deepest_squared(tables.RowRanges(), 0.f);
    ForEachSinglePrecisionRow(mask, tables, [&](int, const float* squares, int range) {
      deepest_squared[range] = std::max(deepest_squared[range], LargestOf(squares, mask.cols));
    });
    return std::sqrt(*std::max_element(deepest_squared.begin(), deepest_squared.end()));
  }
  const int rows = mask.rows, cols = mask.cols;
  // No cell is deeper than its distance along its row or its column: rows in
  // order of the deepest such bound, until it is no more than the deepest
  // cell found.
  std::vector<int32_t> row_bound(rows, 0);
  for (int r = 0; r < rows; ++r) {
    const uint8_t* m = mask.ptr<uint8_t>(r);
    const uint16_t* column = columns.data() + size_t(r) * cols;
    int32_t bound = 0;
    // Along the row, run by run of non-zero cells (zero cells bound nothing):
    // to the zero cell left of the run, and right of it (kNoZero at the
    // mask's edge).
    for (int c = NextNonZero(m, 0, cols); c < cols; c = NextNonZero(m, c, cols)) {
      const int start = c;
      while (c < cols && m[c] != 0) ++c;
      for (int q = start; q < c; ++q) {
        const int left = start > 0 ? q - start + 1 : kNoZero;
        const int right = c < cols ? c - q : kNoZero;
        bound = std::max(bound, std::min({left, right, int(column[q])}));
      }
    }
    row_bound[r] = bound * bound;
  }
  std::vector<int> order(rows);
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](int a, int b) {
    return row_bound[a] != row_bound[b] ? row_bound[a] > row_bound[b] : a < b;
  });
  std::vector<int32_t> f(cols);
  LowerEnvelope envelope(cols);
  int64_t deepest_squared = 0;
  float deepest = 0;
  for (const int r : order) {
    if (row_bound[r] <= deepest_squared) break;
    SquareRow(columns.data() + size_t(r) * cols, cols, f.data());
    ForEachNonZeroCell(mask.ptr<uint8_t>(r), f.data(), cols, envelope, [&](int q, int p) {
      const int64_t d = int64_t(q - p) * (q - p) + f[p];
      if (d <= deepest_squared) return;
      deepest_squared = d;
      deepest = std::max(deepest, DistanceValue(f.data(), q, p));
    });
  }
  return deepest;
}

std::vector<float> DeepestPerLabel(const cv::Mat& mask, const cv::Mat& labels, int count,
                                   const cv::Mat& depth) {
  CV_Assert(mask.type() == CV_8U && labels.type() == CV_32S && labels.size() == mask.size());
  std::vector<float> deepest(count, 0);
  if (mask.empty()) return deepest;
  if (depth.empty() && FitsIntegers(mask) && TooWideForIntegers(mask.cols)) {
    // Maxima of the squares per range, then theirs, then their roots (the
    // root keeps the order).
    const SinglePrecisionTables tables(mask.rows, mask.cols);
    std::vector<std::vector<float>> per_range(tables.RowRanges(), deepest);
    ForEachSinglePrecisionRow(mask, tables, [&](int r, const float* squares, int range) {
      DeepestAlongRow(labels.ptr<int>(r), squares, mask.cols, per_range[range].data());
    });
    for (const std::vector<float>& range : per_range) {
      for (int k = 0; k < count; ++k) deepest[k] = std::max(deepest[k], range[k]);
    }
    for (float& d : deepest) d = std::sqrt(d);
    return deepest;
  }
  const cv::Mat distance = depth.empty() ? ExactDistanceTransform(mask) : depth;
  for (int r = 0; r < mask.rows; ++r) {
    DeepestAlongRow(labels.ptr<int>(r), distance.ptr<float>(r), mask.cols, deepest.data());
  }
  return deepest;
}

std::vector<float> DeepestPerRun(const cv::Mat& mask, const std::vector<PieceRun>& runs,
                                 int count) {
  CV_Assert(mask.type() == CV_8U);
  if (mask.empty() || runs.empty() || !FitsIntegers(mask)) {
    cv::Mat labels = ZerosInParallel(mask.size(), CV_32S);
    for (const PieceRun& run : runs) {
      std::fill(labels.ptr<int>(run.row) + run.begin, labels.ptr<int>(run.row) + run.end,
                run.value);
    }
    std::vector<float> deepest = DeepestPerLabel(mask, labels, count);
    if (!deepest.empty()) deepest[0] = 0;
    return deepest;
  }
  // Every cell's value is OpenCV's, which the exact transform also gives
  // where it applies: the maxima of the squares (per range of rows, then
  // theirs), then their roots. Only rows that hold a run get their squares.
  std::vector<int> order(runs.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(),
                   [&](int a, int b) { return runs[a].row < runs[b].row; });
  const SinglePrecisionTables tables(mask.rows, mask.cols);
  const std::unique_ptr<uint16_t[]> columns = UnsetCells(mask);
  tables.ColumnPass<uint16_t>(mask, [&](int r) { return columns.get() + size_t(r) * mask.cols; });
  std::vector<std::vector<float>> per_range(tables.RowRanges(), std::vector<float>(count, 0.f));
  tables.ForEachRowRange([&](int begin, int end, int index, SinglePrecisionEnvelope& envelope) {
    std::vector<float> squares(mask.cols);
    std::vector<float>& deepest = per_range[index];
    auto next = std::lower_bound(order.begin(), order.end(), begin,
                                 [&](int i, int row) { return runs[i].row < row; });
    while (next != order.end() && runs[*next].row < end) {
      const int r = runs[*next].row;
      envelope.Squares(columns.get() + size_t(r) * mask.cols, squares.data());
      for (; next != order.end() && runs[*next].row == r; ++next) {
        const PieceRun& run = runs[*next];
        float& d = deepest[run.value];
        d = std::max(d, LargestOf(squares.data() + run.begin, run.end - run.begin));
      }
    }
  });
  std::vector<float> deepest(count, 0.f);
  for (const std::vector<float>& range : per_range) {
    for (int k = 0; k < count; ++k) deepest[k] = std::max(deepest[k], range[k]);
  }
  for (float& d : deepest) d = std::sqrt(d);
  return deepest;
}

cv::Mat DistanceAtLeast(const cv::Mat& mask, float reach) {
  CV_Assert(mask.type() == CV_8U);
  const int rows = mask.rows, cols = mask.cols;
  if (mask.empty() || reach <= 0) return cv::Mat(rows, cols, CV_8U, cv::Scalar(1));
  // Every cell is written below.
  cv::Mat at_least(rows, cols, CV_8U);
  const std::vector<uint16_t> columns = ColumnDistances(mask);
  if (columns.empty() && FitsIntegers(mask)) {
    const float threshold = SquaredThreshold(reach);
    const SinglePrecisionTables tables(rows, cols);
    ForEachSinglePrecisionRow(mask, tables, [&](int r, const float* squares, int) {
      uint8_t* out = at_least.ptr<uint8_t>(r);
      const int n = cols;
      const float at = threshold;
      for (int c = 0; c < n; ++c) out[c] = squares[c] >= at ? 1 : 0;
    });
    return at_least;
  }
  if (columns.empty()) {
    cv::Mat distance = OpenCvDistances(mask);
    for (int r = 0; r < rows; ++r) {
      const float* d = distance.ptr<float>(r);
      uint8_t* out = at_least.ptr<uint8_t>(r);
      for (int c = 0; c < cols; ++c) out[c] = d[c] >= reach ? 1 : 0;
    }
    return at_least;
  }
  const int64_t k = SquaredReach(reach);
  // A column whose zero cell is v < sqrt(k) away keeps the cells q of its row
  // with (q - p)^2 < k - v^2 below the reach: those within spread[v] of it.
  std::vector<int> spread;
  for (int64_t v = 0; v * v < k && v < kNoZero; ++v) {
    int64_t t = 0;
    while ((t + 1) * (t + 1) < k - v * v) ++t;
    spread.push_back(int(t));
  }
  const int nearer = int(spread.size());
  ForEachRowRange(rows, cols, [&](int begin, int end) {
    for (int r = begin; r < end; ++r) {
      AtLeastRow(columns.data() + size_t(r) * cols, at_least.ptr<uint8_t>(r), cols, nearer,
                 spread.data());
    }
  });
  return at_least;
}

}  // namespace areagraph

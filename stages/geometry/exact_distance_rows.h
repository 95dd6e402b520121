#pragma once

// The exact path of stages/geometry/distance_transform.cc: column distances
// as integers, squared, and the lower envelope of their parabolas along each
// row. Included by that file only.

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <opencv2/core.hpp>
#include <vector>

#include "stages/geometry/parallel_ranges.h"
#ifdef __SSE2__
#include <immintrin.h>
#endif

namespace areagraph {
namespace distance_rows {

// Squared distances along a row: a column without any zero cell has none.
inline constexpr int32_t kFar = std::numeric_limits<int32_t>::max();
// Distances along a column: from here up, the column has no zero cell (a
// mask at most 32767 cells high counts up to 65535 at most).
inline constexpr uint16_t kNoZero = 1 << 15;

inline bool FitsIntegers(const cv::Mat& mask) { return mask.rows < kNoZero && mask.cols < kNoZero; }

// Whether a row this wide alone breaks ColumnDistances's guard below.
inline bool TooWideForIntegers(int cols) {
  return int64_t(cols - 1) * (cols - 1) >= (int64_t(1) << 24);
}

// One row of ColumnDistances's downward pass: out = 0 on zero cells of
// `mask`, above + 1 elsewhere. Sixteen cells at a time where SSE2 is.
inline void DownRow(const uint8_t* mask, const uint16_t* above, uint16_t* out, int cols) {
  int c = 0;
#ifdef __SSE2__
  const __m128i zero = _mm_setzero_si128(), one = _mm_set1_epi16(1);
  for (; c + 16 <= cols; c += 16) {
    const __m128i is_zero =
        _mm_cmpeq_epi8(_mm_loadu_si128(reinterpret_cast<const __m128i*>(mask + c)), zero);
    const __m128i low = _mm_unpacklo_epi8(is_zero, is_zero);
    const __m128i high = _mm_unpackhi_epi8(is_zero, is_zero);
    const __m128i a0 = _mm_loadu_si128(reinterpret_cast<const __m128i*>(above + c));
    const __m128i a1 = _mm_loadu_si128(reinterpret_cast<const __m128i*>(above + c + 8));
    _mm_storeu_si128(reinterpret_cast<__m128i*>(out + c),
                     _mm_andnot_si128(low, _mm_add_epi16(a0, one)));
    _mm_storeu_si128(reinterpret_cast<__m128i*>(out + c + 8),
                     _mm_andnot_si128(high, _mm_add_epi16(a1, one)));
  }
#endif
  for (; c < cols; ++c) out[c] = mask[c] == 0 ? 0 : uint16_t(above[c] + 1);
}

// One row of ColumnDistances's upward pass: out = below = min(out, below + 1).
// Returns the largest value under kNoZero, or -1 when there is none.
inline int UpRow(uint16_t* out, uint16_t* below, int cols) {
  int c = 0, farthest = -1;
#ifdef __SSE2__
  const __m128i one = _mm_set1_epi16(1);
  __m128i largest = _mm_set1_epi16(-1);
  for (; c + 8 <= cols; c += 8) {
    const __m128i here = _mm_loadu_si128(reinterpret_cast<const __m128i*>(out + c));
    const __m128i next =
        _mm_add_epi16(_mm_loadu_si128(reinterpret_cast<const __m128i*>(below + c)), one);
    // Unsigned minimum: here - max(here - next, 0).
    const __m128i d = _mm_sub_epi16(here, _mm_subs_epu16(here, next));
    _mm_storeu_si128(reinterpret_cast<__m128i*>(out + c), d);
    _mm_storeu_si128(reinterpret_cast<__m128i*>(below + c), d);
    largest = _mm_max_epi16(largest, d);
  }
  int16_t lanes[8];
  _mm_storeu_si128(reinterpret_cast<__m128i*>(lanes), largest);
  for (const int16_t lane : lanes) farthest = std::max<int>(farthest, lane);
#endif
  for (; c < cols; ++c) {
    const uint16_t d = std::min<uint16_t>(out[c], below[c] + 1);
    below[c] = d;
    out[c] = d;
    if (d < kNoZero) farthest = std::max<int>(farthest, d);
  }
  return farthest;
}

// The distance of every cell to the nearest zero cell of its column
// (kNoZero or more when the column has none), row by row. Leaves it empty
// when the result would not be OpenCV's: when the mask has no zero cell
// (OpenCV then gives its stand-in for infinity), or when OpenCV's
// single-precision breakpoints, f[q] + q^2 - f[p] - p^2, are not all exact
// integers (2^24 and above; on masks over 4096 cells wide its distances are
// then not exact, and differ). Then callers take OpenCV's rounding
// (OpenCvDistances).
inline std::vector<uint16_t> ColumnDistances(const cv::Mat& mask) {
  const int rows = mask.rows, cols = mask.cols;
  if (mask.empty() || !FitsIntegers(mask)) return {};
  // The row's width alone breaks the guard below (masks over 4097 cells
  // wide): no need to fill the buffer first (a 50-megapixel map did, 47 MB,
  // for every whole-map transform of clean, cut and merge).
  if (TooWideForIntegers(cols)) return {};
  const int64_t widest = int64_t(cols - 1) * (cols - 1);
  std::vector<uint16_t> distance(size_t(rows) * cols);
  // Downwards: the distance to the nearest zero cell above or at the cell.
  for (int c = 0; c < cols; ++c) distance[c] = mask.ptr<uint8_t>(0)[c] == 0 ? 0 : kNoZero;
  for (int r = 1; r < rows; ++r) {
    DownRow(mask.ptr<uint8_t>(r), distance.data() + size_t(r - 1) * cols,
            distance.data() + size_t(r) * cols, cols);
  }
  // Upwards: the nearer of that and the one below; the largest distance
  // under kNoZero along the way (as int16, those at or above it are
  // negative). A zero cell somewhere gives a distance 0 somewhere.
  std::vector<uint16_t> below(cols, kNoZero);
  int farthest = -1;
  for (int r = rows - 1; r >= 0; --r) {
    farthest = std::max(farthest, UpRow(distance.data() + size_t(r) * cols, below.data(), cols));
  }
  if (farthest < 0 || int64_t(farthest) * farthest + widest >= (int64_t(1) << 24)) return {};
  return distance;
}

// At least this many cells per parallel range of rows or columns (and 8
// rows or columns): a smaller range costs more to start than it gains.
inline constexpr size_t kMinRangeCells = size_t(1) << 16;

// How many parallel ranges `rows` rows of `cols` cells are split into.
inline int RowRangeCount(int rows, int cols) {
  return ParallelRangeCount(size_t(rows), std::max<size_t>(8, kMinRangeCells / std::max(cols, 1)));
}

// Calls body(begin, end) for RowRangeCount contiguous ranges of [0, rows), in
// parallel (each row's work is its own).
template <typename Body>
inline void ForEachRowRange(int rows, int cols, const Body& body) {
  ForEachRange(size_t(rows), RowRangeCount(rows, cols),
               [&](size_t begin, size_t end, int) { body(int(begin), int(end)); });
}

// One row of ColumnDistances, squared.
inline void SquareRow(const uint16_t* distance, int cols, int32_t* f) {
  for (int c = 0; c < cols; ++c) {
    f[c] = distance[c] >= kNoZero ? kFar : int32_t(distance[c]) * distance[c];
  }
}

// Felzenszwalb and Huttenlocher's lower envelope of the parabolas
// f[p] + (x - p)^2, p in [lo, hi] (columns at kFar left out), evaluated at
// x = q for q in [from, to): calls emit(q, p) with a minimising p. At least one
// column of [lo, hi] must be finite. The breakpoints are quotients of exact
// integers, rounded once, so equal ones compare equal and unequal ones apart.
class LowerEnvelope {
 public:
  explicit LowerEnvelope(int cols) : v_(cols), g_(cols), z_(cols + 1) {}

  template <typename Emit>
  void Evaluate(const int32_t* f, int lo, int hi, int from, int to, Emit emit) {
    int k = -1;
    for (int q = lo; q <= hi; ++q) {
      if (f[q] == kFar) continue;
      const int64_t g = int64_t(f[q]) + int64_t(q) * q;
      double s = -std::numeric_limits<double>::infinity();
      while (k >= 0) {
        s = double(g - g_[k]) / double(2 * (q - v_[k]));
        if (s > z_[k]) break;
        --k;
      }
      ++k;
      v_[k] = q;
      g_[k] = g;
      z_[k] = k == 0 ? -std::numeric_limits<double>::infinity() : s;
    }
    const int last = k;
    k = 0;
    for (int q = from; q < to; ++q) {
      while (k < last && z_[k + 1] <= q) ++k;
      emit(q, v_[k]);
    }
  }

 private:
  std::vector<int> v_;
  std::vector<int64_t> g_;
  std::vector<double> z_;
};

// The distance as OpenCV's DIST_MASK_PRECISE gives it: the square root, in
// single precision, of the sum of the squared offsets along the row and the
// column.
inline float DistanceValue(const int32_t* f, int q, int p) {
  return std::sqrt(float((q - p) * (q - p)) + float(f[p]));
}

// The first column from `c` on where the row of `mask` is not zero, or cols.
inline int NextNonZero(const uint8_t* mask, int c, int cols) {
  // Eight cells at a time across the stretches of zero cells.
  for (; c + 8 <= cols; c += 8) {
    uint64_t eight;
    std::memcpy(&eight, mask + c, sizeof(eight));
    if (eight != 0) break;
  }
  while (c < cols && mask[c] == 0) ++c;
  return c;
}

// Calls emit(q, p) for every non-zero cell q of one row (`mask`, and f: its
// squared column distances) with p its nearest column. Only the run of
// non-zero cells around q and the zero cells that bound it matter: any column
// beyond such a zero cell is farther than the zero cell itself.
template <typename Emit>
inline void ForEachNonZeroCell(const uint8_t* mask, const int32_t* f, int cols,
                               LowerEnvelope& envelope, Emit emit) {
  int c = 0;
  while (c < cols) {
    c = NextNonZero(mask, c, cols);
    if (c == cols) break;
    const int start = c;
    while (c < cols && mask[c] != 0) ++c;
    envelope.Evaluate(f, std::max(start - 1, 0), std::min(c, cols - 1), start, c, emit);
  }
}

}  // namespace distance_rows
}  // namespace areagraph

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

#include "stages/geometry/parallel_ranges.h"
#include "stages/geometry/parallel_zeros.h"
#ifdef __SSE2__
#include <immintrin.h>
#endif

namespace areagraph {
namespace {

// Squared distances along a row: a column without any zero cell has none.
constexpr int32_t kFar = std::numeric_limits<int32_t>::max();
// Distances along a column: from here up, the column has no zero cell (a
// mask at most 32767 cells high counts up to 65535 at most).
constexpr uint16_t kNoZero = 1 << 15;

bool FitsIntegers(const cv::Mat& mask) { return mask.rows < kNoZero && mask.cols < kNoZero; }

// Whether a row this wide alone breaks ColumnDistances's guard below.
bool TooWideForIntegers(int cols) { return int64_t(cols - 1) * (cols - 1) >= (int64_t(1) << 24); }

// One row of ColumnDistances's downward pass: out = 0 on zero cells of
// `mask`, above + 1 elsewhere. Sixteen cells at a time where SSE2 is.
void DownRow(const uint8_t* mask, const uint16_t* above, uint16_t* out, int cols) {
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
int UpRow(uint16_t* out, uint16_t* below, int cols) {
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
std::vector<uint16_t> ColumnDistances(const cv::Mat& mask) {
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
constexpr size_t kMinRangeCells = size_t(1) << 16;

// How many parallel ranges `rows` rows of `cols` cells are split into.
int RowRangeCount(int rows, int cols) {
  return ParallelRangeCount(size_t(rows), std::max<size_t>(8, kMinRangeCells / std::max(cols, 1)));
}

// Calls body(begin, end) for RowRangeCount contiguous ranges of [0, rows), in
// parallel (each row's work is its own).
template <typename Body>
void ForEachRowRange(int rows, int cols, const Body& body) {
  ForEachRange(size_t(rows), RowRangeCount(rows, cols),
               [&](size_t begin, size_t end, int) { body(int(begin), int(end)); });
}

// One row of ColumnDistances, squared.
void SquareRow(const uint16_t* distance, int cols, int32_t* f) {
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
float DistanceValue(const int32_t* f, int q, int p) {
  return std::sqrt(float((q - p) * (q - p)) + float(f[p]));
}

// The first column from `c` on where the row of `mask` is not zero, or cols.
int NextNonZero(const uint8_t* mask, int c, int cols) {
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
void ForEachNonZeroCell(const uint8_t* mask, const int32_t* f, int cols, LowerEnvelope& envelope,
                        Emit emit) {
  int c = 0;
  while (c < cols) {
    c = NextNonZero(mask, c, cols);
    if (c == cols) break;
    const int start = c;
    while (c < cols && mask[c] != 0) ++c;
    envelope.Evaluate(f, std::max(start - 1, 0), std::min(c, cols - 1), start, c, emit);
  }
}

// cv::distanceTransform(mask, out, DIST_L2, DIST_MASK_PRECISE) as OpenCV 4.6
// computes it, rounding for rounding: squares as floats (float(i * i)), a
// column's squared distance to its nearest zero cell (1e15 where it has
// none), then per row the lower envelope of the parabolas with breakpoints
// (f[q] + q^2 - f[p] - p^2) times float(0.5 / (q - p)), each step rounded to
// single precision in that order, and the square root of (q - p)^2 + f[p].
// Ours for speed on large masks: OpenCV walks each column down the whole mask
// (a cache miss per cell once a column outgrows the cache: a 50-megapixel map
// spent 2 s of merge's 8 there); here the columns go row by row, and the
// rows, each on its own once the column distances are known, in parallel
// ranges. Tests hold it to OpenCV bit for bit, masks over 4096 wide included.
class SinglePrecisionTables {
 public:
  SinglePrecisionTables(int rows, int cols)
      : rows_(rows), cols_(cols), square_(std::max(rows, cols)), half_inverse_(cols, 0.f) {
    for (size_t i = 0; i < square_.size(); ++i) square_[i] = float(int(i) * int(i));
    for (int i = 1; i < cols; ++i) half_inverse_[i] = float(0.5 / i);
  }

  int rows() const { return rows_; }
  int cols() const { return cols_; }

  // Every cell's distance to the nearest zero cell of its column into
  // `row(r)` (T* rows of the mask's size); `rows` or more where the column
  // has none. Column ranges in parallel: each walks down, then up.
  template <typename T, typename Row>
  void ColumnPass(const cv::Mat& mask, Row row) const {
    const int rows = rows_;
    ForEachRange(size_t(cols_), RowRangeCount(cols_, rows), [&](size_t begin, size_t end, int) {
      const int c0 = int(begin), c1 = int(end);
      for (int r = 0; r < rows; ++r) {
        const uint8_t* m = mask.ptr<uint8_t>(r);
        T* out = row(r);
        const T* above = r > 0 ? row(r - 1) : nullptr;
        for (int c = c0; c < c1; ++c) {
          out[c] = m[c] == 0 ? 0 : (above ? T(above[c] + 1) : T(rows));
        }
      }
      for (int r = rows - 2; r >= 0; --r) {
        T* out = row(r);
        const T* below = row(r + 1);
        for (int c = c0; c < c1; ++c) out[c] = std::min<T>(out[c], T(below[c] + 1));
      }
    });
  }

  // How many ranges ForEachRowRange splits the rows into.
  int RowRanges() const { return RowRangeCount(rows_, cols_); }

  // Calls each_range(begin, end, index, envelope) for RowRanges() contiguous
  // ranges of rows, in parallel; the envelope's Squares gives those rows'
  // squared distances.
  template <typename EachRange>
  void ForEachRowRange(const EachRange& each_range) const;

  const float* square() const { return square_.data(); }
  const float* half_inverse() const { return half_inverse_.data(); }

 private:
  int rows_, cols_;
  std::vector<float> square_, half_inverse_;
};

// One thread's lower envelope along rows of SinglePrecisionTables.
class SinglePrecisionEnvelope {
 public:
  explicit SinglePrecisionEnvelope(const SinglePrecisionTables& tables)
      : rows_(tables.rows()),
        cols_(tables.cols()),
        square_(tables.square()),
        half_inverse_(tables.half_inverse()),
        f_(cols_),
        z_(size_t(cols_) + 1),
        v_(cols_) {}

  // One row's squared distances, (q - p)^2 + f[p] before the square root,
  // from its column distances (ColumnPass). `out` may be `column` itself.
  template <typename T>
  void Squares(const T* column, float* out) {
    for (int c = 0; c < cols_; ++c) {
      const int d = int(column[c]);
      f_[c] = d < rows_ ? square_[d] : kInfinity;
    }
    // The top parabola stays in registers (OpenCV's loop reads it back from
    // the arrays it has just written); the same operations in the same order.
    int k = 0, p = 0;
    v_[0] = 0;
    z_[0] = -kInfinity;
    float top_z = -kInfinity, top_f = f_[0], top_square = square_[0];
    for (int q = 1; q < cols_; ++q) {
      const float g = f_[q] + square_[q];
      for (;;) {
        const float s = (g - top_f - top_square) * half_inverse_[q - p];
        if (s > top_z) {
          v_[++k] = p = q;
          z_[k] = top_z = s;
          top_f = f_[q];
          top_square = square_[q];
          break;
        }
        p = v_[--k];
        top_z = z_[k];
        top_f = f_[p];
        top_square = square_[p];
      }
    }
    z_[k + 1] = kInfinity;
    k = 0;
    for (int q = 0; q < cols_; ++q) {
      while (z_[k + 1] < float(q)) ++k;
      const int p = v_[k];
      out[q] = square_[std::abs(q - p)] + f_[p];
    }
  }

 private:
  static constexpr float kInfinity = 1e15f;
  int rows_, cols_;
  const float* square_;
  const float* half_inverse_;
  std::vector<float> f_, z_;
  std::vector<int> v_;
};

template <typename EachRange>
void SinglePrecisionTables::ForEachRowRange(const EachRange& each_range) const {
  ForEachRange(size_t(rows_), RowRanges(), [&](size_t begin, size_t end, int index) {
    SinglePrecisionEnvelope envelope(*this);
    each_range(int(begin), int(end), index, envelope);
  });
}

// x = sqrt(x) for n floats. Four at a time where SSE is: sqrtps rounds as
// sqrtss does (correctly), and std::sqrt's loop stays scalar for errno.
void SquareRoots(float* x, int n) {
  int i = 0;
#ifdef __SSE2__
  for (; i + 4 <= n; i += 4) _mm_storeu_ps(x + i, _mm_sqrt_ps(_mm_loadu_ps(x + i)));
#endif
  for (; i < n; ++i) x[i] = std::sqrt(x[i]);
}

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

cv::Mat SinglePrecisionDistances(const cv::Mat& mask) {
  const SinglePrecisionTables tables(mask.rows, mask.cols);
  // The column distances first go where the result will be (no second
  // buffer: on this project's virtual machines each new page costs a fault
  // of 20-50 microseconds), as int32.
  cv::Mat distance(mask.rows, mask.cols, CV_32F);
  tables.ColumnPass<int32_t>(mask, [&](int r) { return distance.ptr<int32_t>(r); });
  tables.ForEachRowRange([&](int begin, int end, int, SinglePrecisionEnvelope& envelope) {
    for (int r = begin; r < end; ++r) {
      float* out = distance.ptr<float>(r);
      envelope.Squares(distance.ptr<int32_t>(r), out);
      SquareRoots(out, mask.cols);
    }
  });
  return distance;
}

// A buffer of one uint16_t a cell of `mask`, not zeroed: ColumnPass writes
// every cell, and zeroing first (47 MB at 50 megapixels, on one thread) only
// faulted the pages in.
std::unique_ptr<uint16_t[]> UnsetCells(const cv::Mat& mask) {
  return std::unique_ptr<uint16_t[]>(new uint16_t[size_t(mask.rows) * mask.cols]);
}

// Calls each_row(r, squares, range) with row r's squared single-precision
// distances (SinglePrecisionDistances before the square root), without the
// float image (the column distances take half its size): rows in
// `tables.RowRanges()` parallel ranges, in order within each, `range` the
// range's index. For callers that threshold or take maxima: the square root,
// correctly rounded, keeps the order of its inputs.
template <typename EachRow>
void ForEachSinglePrecisionRow(const cv::Mat& mask, const SinglePrecisionTables& tables,
                               EachRow each_row) {
  const std::unique_ptr<uint16_t[]> columns = UnsetCells(mask);
  tables.ColumnPass<uint16_t>(mask, [&](int r) { return columns.get() + size_t(r) * mask.cols; });
  tables.ForEachRowRange([&](int begin, int end, int index, SinglePrecisionEnvelope& envelope) {
    std::vector<float> squares(mask.cols);
    for (int r = begin; r < end; ++r) {
      envelope.Squares(columns.get() + size_t(r) * mask.cols, squares.data());
      each_row(r, squares.data(), index);
    }
  });
}

// The least float x with std::sqrt(x) >= reach (> 0).
float SquaredThreshold(float reach) {
  float x = reach * reach;
  while (x > 0 && std::sqrt(std::nextafter(x, 0.f)) >= reach) x = std::nextafter(x, 0.f);
  while (std::sqrt(x) < reach) x = std::nextafter(x, std::numeric_limits<float>::infinity());
  return x;
}

cv::Mat OpenCvDistances(const cv::Mat& mask) {
  if (!mask.empty() && FitsIntegers(mask)) return SinglePrecisionDistances(mask);
  cv::Mat distance;
  cv::distanceTransform(mask, distance, cv::DIST_L2, cv::DIST_MASK_PRECISE);
  return distance;
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

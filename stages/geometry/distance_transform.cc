#include "stages/geometry/distance_transform.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <numeric>
#include <opencv2/imgproc.hpp>
#include <vector>
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
  // wide): no need to fill the buffer first (lab_a tiled 8 x 8 did, 47 MB,
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
// (a cache miss per cell once a column outgrows the cache: lab_a tiled 8 x 8
// spent 2 s of merge's 8 there); here the columns go row by row. Tests hold it
// to OpenCV bit for bit, masks over 4096 wide included.
class SinglePrecisionRows {
 public:
  SinglePrecisionRows(int rows, int cols)
      : rows_(rows),
        cols_(cols),
        square_(std::max(rows, cols)),
        half_inverse_(cols, 0.f),
        f_(cols),
        z_(size_t(cols) + 1),
        v_(cols),
        below_(cols, std::numeric_limits<int>::max() - 1) {
    for (size_t i = 0; i < square_.size(); ++i) square_[i] = float(int(i) * int(i));
    for (int i = 1; i < cols; ++i) half_inverse_[i] = float(0.5 / i);
  }

  // Every cell's distance to the nearest zero cell above or at it in its
  // column into `row(r)` (T* rows of the mask's size); `rows` or more where
  // there is none.
  template <typename T, typename Row>
  void DownDistances(const cv::Mat& mask, Row row) const {
    for (int r = 0; r < rows_; ++r) {
      const uint8_t* m = mask.ptr<uint8_t>(r);
      T* out = row(r);
      const T* above = r > 0 ? row(r - 1) : nullptr;
      for (int c = 0; c < cols_; ++c) out[c] = m[c] == 0 ? 0 : (above ? T(above[c] + 1) : T(rows_));
    }
  }

  // Squares' column step alone, for a row whose distances are not wanted.
  template <typename T>
  void PassRow(const T* down) {
    for (int c = 0; c < cols_; ++c) below_[c] = std::min(int(down[c]), below_[c] + 1);
  }

  // One row's squared distances, (q - p)^2 + f[p] before the square root,
  // from its DownDistances; rows go from the last up (each takes the nearer
  // of its own and the one below's plus 1, as OpenCV's upward pass does).
  // `out` may be `down` itself.
  template <typename T>
  void Squares(const T* down, float* out) {
    for (int c = 0; c < cols_; ++c) {
      const int d = std::min(int(down[c]), below_[c] + 1);
      below_[c] = d;
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
  std::vector<float> square_, half_inverse_, f_, z_;
  std::vector<int> v_, below_;
};

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
  SinglePrecisionRows rows(mask.rows, mask.cols);
  // The column distances first go where the result will be (no second
  // buffer: on this project's virtual machines each new page costs a fault
  // of 20-50 microseconds), as int32.
  cv::Mat distance(mask.rows, mask.cols, CV_32F);
  rows.DownDistances<int32_t>(mask, [&](int r) { return distance.ptr<int32_t>(r); });
  for (int r = mask.rows - 1; r >= 0; --r) {
    float* out = distance.ptr<float>(r);
    rows.Squares(distance.ptr<int32_t>(r), out);
    SquareRoots(out, mask.cols);
  }
  return distance;
}

// Calls each_row(r, squares) with row r's squared single-precision distances
// (SinglePrecisionDistances before the square root), without the float image:
// the column distances take half its size. For callers that threshold or take
// maxima: the square root, correctly rounded, keeps the order of its inputs.
template <typename EachRow>
void ForEachSinglePrecisionRow(const cv::Mat& mask, EachRow each_row) {
  SinglePrecisionRows rows(mask.rows, mask.cols);
  std::vector<uint16_t> columns(size_t(mask.rows) * mask.cols);
  rows.DownDistances<uint16_t>(mask, [&](int r) { return columns.data() + size_t(r) * mask.cols; });
  std::vector<float> squares(mask.cols);
  for (int r = mask.rows - 1; r >= 0; --r) {
    rows.Squares(columns.data() + size_t(r) * mask.cols, squares.data());
    each_row(r, squares.data());
  }
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
  cv::Mat distance = cv::Mat::zeros(rows, cols, CV_32F);
  std::vector<int32_t> f(cols);
  LowerEnvelope envelope(cols);
  for (int r = 0; r < rows; ++r) {
    SquareRow(columns.data() + size_t(r) * cols, cols, f.data());
    float* out = distance.ptr<float>(r);
    ForEachNonZeroCell(mask.ptr<uint8_t>(r), f.data(), cols, envelope,
                       [&](int q, int p) { out[q] = DistanceValue(f.data(), q, p); });
  }
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
    float deepest_squared = 0;
    ForEachSinglePrecisionRow(mask, [&](int, const float* squares) {
      deepest_squared = std::max(deepest_squared, LargestOf(squares, mask.cols));
    });
    return std::sqrt(deepest_squared);
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
    // Maxima of the squares, then their roots (the root keeps the order).
    ForEachSinglePrecisionRow(mask, [&](int r, const float* squares) {
      DeepestAlongRow(labels.ptr<int>(r), squares, mask.cols, deepest.data());
    });
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
    cv::Mat labels = cv::Mat::zeros(mask.size(), CV_32S);
    for (const PieceRun& run : runs) {
      std::fill(labels.ptr<int>(run.row) + run.begin, labels.ptr<int>(run.row) + run.end,
                run.value);
    }
    std::vector<float> deepest = DeepestPerLabel(mask, labels, count);
    if (!deepest.empty()) deepest[0] = 0;
    return deepest;
  }
  // Every cell's value is OpenCV's, which the exact transform also gives
  // where it applies: the maxima of the squares, then their roots.
  std::vector<int> order(runs.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](int a, int b) { return runs[a].row > runs[b].row; });
  SinglePrecisionRows rows(mask.rows, mask.cols);
  std::vector<uint16_t> columns(size_t(mask.rows) * mask.cols);
  rows.DownDistances<uint16_t>(mask, [&](int r) { return columns.data() + size_t(r) * mask.cols; });
  std::vector<float> squares(mask.cols), deepest(count, 0);
  size_t next = 0;
  for (int r = mask.rows - 1; r >= 0; --r) {
    const uint16_t* down = columns.data() + size_t(r) * mask.cols;
    if (next == order.size() || runs[order[next]].row != r) {
      rows.PassRow(down);
      continue;
    }
    rows.Squares(down, squares.data());
    for (; next < order.size() && runs[order[next]].row == r; ++next) {
      const PieceRun& run = runs[order[next]];
      float& d = deepest[run.value];
      d = std::max(d, LargestOf(squares.data() + run.begin, run.end - run.begin));
    }
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
    ForEachSinglePrecisionRow(mask, [&](int r, const float* squares) {
      uint8_t* out = at_least.ptr<uint8_t>(r);
      for (int c = 0; c < cols; ++c) out[c] = squares[c] >= threshold ? 1 : 0;
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
  for (int r = 0; r < rows; ++r) {
    const uint16_t* v = columns.data() + size_t(r) * cols;
    uint8_t* out = at_least.ptr<uint8_t>(r);
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
  return at_least;
}

}  // namespace areagraph

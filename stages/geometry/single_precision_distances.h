#pragma once

// OpenCV's single-precision rounding of the distance transform, reproduced
// (stages/geometry/distance_transform.cc takes it where the exact integers
// would differ from OpenCV's result). Included by that file only.

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <opencv2/imgproc.hpp>
#include <vector>

#include "stages/geometry/exact_distance_rows.h"
#include "stages/geometry/parallel_ranges.h"
#ifdef __SSE2__
#include <immintrin.h>
#endif

namespace areagraph {
namespace distance_rows {

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
inline void SquareRoots(float* x, int n) {
  int i = 0;
#ifdef __SSE2__
  for (; i + 4 <= n; i += 4) _mm_storeu_ps(x + i, _mm_sqrt_ps(_mm_loadu_ps(x + i)));
#endif
  for (; i < n; ++i) x[i] = std::sqrt(x[i]);
}

inline cv::Mat SinglePrecisionDistances(const cv::Mat& mask) {
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
inline std::unique_ptr<uint16_t[]> UnsetCells(const cv::Mat& mask) {
  return std::unique_ptr<uint16_t[]>(new uint16_t[size_t(mask.rows) * mask.cols]);
}

// Calls each_row(r, squares, range) with row r's squared single-precision
// distances (SinglePrecisionDistances before the square root), without the
// float image (the column distances take half its size): rows in
// `tables.RowRanges()` parallel ranges, in order within each, `range` the
// range's index. For callers that threshold or take maxima: the square root,
// correctly rounded, keeps the order of its inputs.
template <typename EachRow>
inline void ForEachSinglePrecisionRow(const cv::Mat& mask, const SinglePrecisionTables& tables,
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
inline float SquaredThreshold(float reach) {
  float x = reach * reach;
  while (x > 0 && std::sqrt(std::nextafter(x, 0.f)) >= reach) x = std::nextafter(x, 0.f);
  while (std::sqrt(x) < reach) x = std::nextafter(x, std::numeric_limits<float>::infinity());
  return x;
}

inline cv::Mat OpenCvDistances(const cv::Mat& mask) {
  if (!mask.empty() && FitsIntegers(mask)) return SinglePrecisionDistances(mask);
  cv::Mat distance;
  cv::distanceTransform(mask, distance, cv::DIST_L2, cv::DIST_MASK_PRECISE);
  return distance;
}

}  // namespace distance_rows
}  // namespace areagraph

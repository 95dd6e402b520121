#pragma once

#include <algorithm>
#include <cstring>
#include <opencv2/core.hpp>

#include "stages/geometry/parallel_ranges.h"

namespace areagraph {

// cv::Mat::zeros(size, type) with the rows cleared in parallel ranges: on a
// big map most of the time of zeroing a fresh buffer is the first touch of
// its pages, which the pool's threads then share. The buffer is allocated
// by the calling thread (its malloc arena), as cv::Mat::zeros would.
inline cv::Mat ZerosInParallel(cv::Size size, int type) {
  cv::Mat zeros(size, type);
  const size_t row_bytes = zeros.cols * zeros.elemSize();
  // At least 1 MB a range: smaller ones cost more to start than they gain.
  const size_t min_rows = std::max<size_t>(1, (size_t(1) << 20) / std::max<size_t>(row_bytes, 1));
  const size_t rows = static_cast<size_t>(zeros.rows);
  ForEachRange(rows, ParallelRangeCount(rows, min_rows), [&](size_t begin, size_t end, int) {
    for (size_t r = begin; r < end; ++r) std::memset(zeros.ptr(static_cast<int>(r)), 0, row_bytes);
  });
  return zeros;
}

}  // namespace areagraph

#include "stages/geometry/wall_thickness.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>
#ifdef __SSE2__
#include <immintrin.h>
#endif

#include "proto/artifacts.pb.h"
#include "stages/geometry/distance_transform.h"

namespace areagraph {

cv::Mat ObstacleMask(const std::string& cells, int width, int height) {
  cv::Mat obstacle(height, width, CV_8U);
  // Through local pointers: the byte stores may alias the string's buffer,
  // so indexing the string would reload it per cell and not vectorise.
  const auto* in = reinterpret_cast<const uint8_t*>(cells.data());
  uint8_t* out = obstacle.data;
  const size_t count = static_cast<size_t>(width) * static_cast<size_t>(height);
  for (size_t index = 0; index < count; ++index) {
    out[index] = in[index] == proto::CELL_FREE ? 0 : 255;
  }
  return obstacle;
}

cv::Mat ObstacleDepth(const cv::Mat& obstacle) {
  // Most cells are free: the exact transform works on the others only.
  return ExactDistanceTransform(obstacle);
}

namespace {

// The largest float d with float(2 * d) <= max_wall_px (as double): the
// ridge test's bound, for comparing floats with floats.
float HalfBound(double max_wall_px) {
  // NaN: `2 * d > max_wall_px` never holds, so every depth passes.
  if (std::isnan(max_wall_px)) return std::numeric_limits<float>::infinity();
  float d = float(max_wall_px / 2);
  auto passes = [&](float x) { return double(2 * x) <= max_wall_px; };
  while (!passes(d)) d = std::nextafter(d, -std::numeric_limits<float>::infinity());
  for (float up = std::nextafter(d, std::numeric_limits<float>::infinity()); up != d && passes(up);
       up = std::nextafter(d, std::numeric_limits<float>::infinity())) {
    d = up;
  }
  return d;
}

// Whether cell c of row `here` is a ridge top: deeper than 0, within the
// bound, and at least as deep as all 8 neighbours.
bool RidgeTop(const float* above, const float* here, const float* below, int c, float bound) {
  const float d = here[c];
  return d > 0 && d <= bound && above[c - 1] <= d && above[c] <= d && above[c + 1] <= d &&
         here[c - 1] <= d && here[c + 1] <= d && below[c - 1] <= d && below[c] <= d &&
         below[c + 1] <= d;
}

}  // namespace

double TypicalWallThickness(const cv::Mat& depth, double max_wall_px) {
  const float bound = HalfBound(max_wall_px);
  std::vector<float> ridge;
  for (int r = 1; r + 1 < depth.rows; ++r) {
    const float* above = depth.ptr<float>(r - 1);
    const float* here = depth.ptr<float>(r);
    const float* below = depth.ptr<float>(r + 1);
    int c = 1;
#ifdef __SSE2__
    // Four cells at a time, the same comparisons (false on NaN as there).
    const __m128 zero = _mm_setzero_ps(), top = _mm_set1_ps(bound);
    for (; c + 4 < depth.cols; c += 4) {
      const __m128 d = _mm_loadu_ps(here + c);
      __m128 is_top = _mm_and_ps(_mm_cmpgt_ps(d, zero), _mm_cmple_ps(d, top));
      if (_mm_movemask_ps(is_top) == 0) continue;
      for (const float* row : {above, here, below}) {
        for (const int dc : {-1, 0, 1}) {
          if (row == here && dc == 0) continue;
          is_top = _mm_and_ps(is_top, _mm_cmple_ps(_mm_loadu_ps(row + c + dc), d));
        }
      }
      const int bits = _mm_movemask_ps(is_top);
      for (int k = 0; k < 4; ++k) {
        if (bits & (1 << k)) ridge.push_back(2 * here[c + k]);
      }
    }
#endif
    for (; c + 1 < depth.cols; ++c) {
      if (RidgeTop(above, here, below, c, bound)) ridge.push_back(2 * here[c]);
    }
  }
  // The median's value does not depend on the order the ridge was found in.
  if (ridge.empty()) return 0;
  std::nth_element(ridge.begin(), ridge.begin() + ridge.size() / 2, ridge.end());
  return ridge[ridge.size() / 2];
}

}  // namespace areagraph

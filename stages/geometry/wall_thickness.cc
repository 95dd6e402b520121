#include "stages/geometry/wall_thickness.h"

#include <algorithm>
#include <vector>

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

double TypicalWallThickness(const cv::Mat& depth, double max_wall_px) {
  std::vector<float> ridge;
  for (int r = 1; r + 1 < depth.rows; ++r) {
    const float* above = depth.ptr<float>(r - 1);
    const float* here = depth.ptr<float>(r);
    const float* below = depth.ptr<float>(r + 1);
    for (int c = 1; c + 1 < depth.cols; ++c) {
      const float d = here[c];
      if (d <= 0 || 2 * d > max_wall_px) continue;
      const bool top = above[c - 1] <= d && above[c] <= d && above[c + 1] <= d &&
                       here[c - 1] <= d && here[c + 1] <= d && below[c - 1] <= d && below[c] <= d &&
                       below[c + 1] <= d;
      if (top) ridge.push_back(2 * d);
    }
  }
  if (ridge.empty()) return 0;
  std::nth_element(ridge.begin(), ridge.begin() + ridge.size() / 2, ridge.end());
  return ridge[ridge.size() / 2];
}

}  // namespace areagraph

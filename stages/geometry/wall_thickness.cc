#include "stages/geometry/wall_thickness.h"

#include <algorithm>
#include <opencv2/imgproc.hpp>
#include <vector>

#include "proto/artifacts.pb.h"

namespace areagraph {

cv::Mat ObstacleMask(const std::string& cells, int width, int height) {
  cv::Mat obstacle(height, width, CV_8U);
  for (int index = 0; index < width * height; ++index) {
    obstacle.data[index] = cells[index] == proto::CELL_FREE ? 0 : 255;
  }
  return obstacle;
}

cv::Mat ObstacleDepth(const cv::Mat& obstacle) {
  cv::Mat depth;
  cv::distanceTransform(obstacle, depth, cv::DIST_L2, cv::DIST_MASK_PRECISE);
  return depth;
}

double TypicalWallThickness(const cv::Mat& depth, double max_wall_px) {
  std::vector<float> ridge;
  for (int r = 1; r + 1 < depth.rows; ++r) {
    for (int c = 1; c + 1 < depth.cols; ++c) {
      const float d = depth.at<float>(r, c);
      if (d <= 0 || 2 * d > max_wall_px) continue;
      bool top = true;
      for (int dr = -1; dr <= 1 && top; ++dr) {
        for (int dc = -1; dc <= 1; ++dc) top &= depth.at<float>(r + dr, c + dc) <= d;
      }
      if (top) ridge.push_back(2 * d);
    }
  }
  if (ridge.empty()) return 0;
  std::nth_element(ridge.begin(), ridge.begin() + ridge.size() / 2, ridge.end());
  return ridge[ridge.size() / 2];
}

}  // namespace areagraph

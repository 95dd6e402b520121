// TypicalWallThickness skips four cells at a time past those outside
// (0, max_wall_px / 2]; held to the cell-by-cell definition.
#include "stages/geometry/wall_thickness.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <opencv2/imgproc.hpp>
#include <random>
#include <vector>

#include "stages/geometry/distance_transform.h"

namespace areagraph {
namespace {

// The definition, cell by cell: the median of twice the depth over the cells
// at least as deep as their 8 neighbours, deeper than 0, with twice the depth
// not over max_wall_px.
double ReferenceThickness(const cv::Mat& depth, double max_wall_px) {
  std::vector<float> ridge;
  for (int r = 1; r + 1 < depth.rows; ++r) {
    for (int c = 1; c + 1 < depth.cols; ++c) {
      const float d = depth.at<float>(r, c);
      if (d <= 0 || 2 * d > max_wall_px) continue;
      bool top = true;
      for (int dr = -1; dr <= 1; ++dr) {
        for (int dc = -1; dc <= 1; ++dc) top = top && depth.at<float>(r + dr, c + dc) <= d;
      }
      if (top) ridge.push_back(2 * d);
    }
  }
  if (ridge.empty()) return 0;
  std::sort(ridge.begin(), ridge.end());
  return ridge[ridge.size() / 2];
}

TEST(TypicalWallThickness, EqualsTheCellByCellDefinition) {
  std::mt19937 random(8);
  for (int trial = 0; trial < 80; ++trial) {
    const int rows = 1 + int(random() % 60), cols = 1 + int(random() % 70);
    // Walls and blocks of 1-6 cells on free space, as depth.
    cv::Mat obstacle(rows, cols, CV_8U, cv::Scalar(0));
    for (int k = 0; k < 12; ++k) {
      const cv::Point a(int(random() % cols), int(random() % rows));
      const cv::Point b(int(random() % cols), int(random() % rows));
      cv::line(obstacle, a, b, cv::Scalar(255), 1 + int(random() % 6));
    }
    const cv::Mat depth = ExactDistanceTransform(obstacle);
    // Bounds at, between and around twice the depths that occur.
    for (const double max_wall : {0.0, 1.0, 2.0, 2.0 * std::sqrt(2.0f), 2.0 * std::sqrt(5.0f),
                                  2.0 * std::sqrt(5.0f) - 1e-12, 4.5, 6.0, 1e9}) {
      ASSERT_EQ(TypicalWallThickness(depth, max_wall), ReferenceThickness(depth, max_wall))
          << cols << " x " << rows << ", max " << max_wall;
    }
  }
}

TEST(TypicalWallThickness, RandomDepthsWithTiesAndNoBound) {
  std::mt19937 random(9);
  for (int trial = 0; trial < 40; ++trial) {
    cv::Mat depth(3 + int(random() % 20), 3 + int(random() % 40), CV_32F);
    // Few distinct values: plateaus of equal depth, zeros, negatives.
    for (int r = 0; r < depth.rows; ++r) {
      for (int c = 0; c < depth.cols; ++c) depth.at<float>(r, c) = float(int(random() % 5) - 1);
    }
    for (const double max_wall : {2.0, 3.9, 4.0, 6.0, std::numeric_limits<double>::quiet_NaN()}) {
      EXPECT_EQ(TypicalWallThickness(depth, max_wall), ReferenceThickness(depth, max_wall))
          << depth.cols << " x " << depth.rows << ", max " << max_wall;
    }
  }
}

}  // namespace
}  // namespace areagraph

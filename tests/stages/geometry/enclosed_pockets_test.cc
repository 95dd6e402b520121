#include "stages/geometry/enclosed_pockets.h"

#include <gtest/gtest.h>

#include <opencv2/imgproc.hpp>
#include <random>

namespace areagraph {
namespace {

// A 60 x 40 free map, walled around, with an outlined desk (a 12 x 8 ring,
// 1 cell thick) and a ring 30 cells long in its free space.
cv::Mat MapWithOutlines() {
  cv::Mat obstacle(40, 60, CV_8U, cv::Scalar(0));
  cv::rectangle(obstacle, cv::Rect(0, 0, 60, 40), cv::Scalar(255));
  cv::rectangle(obstacle, cv::Rect(5, 5, 12, 8), cv::Scalar(255));
  cv::rectangle(obstacle, cv::Rect(20, 20, 30, 10), cv::Scalar(255));
  return obstacle;
}

TEST(EnclosedPockets, FillsTheInsideOfSmallOutlinesOnly) {
  cv::Mat obstacle = MapWithOutlines();
  FillEnclosedPockets(20, &obstacle);
  EXPECT_EQ(obstacle.at<uint8_t>(9, 10), 255);  // inside the desk outline
  EXPECT_EQ(obstacle.at<uint8_t>(25, 35), 0);   // inside the long ring
  EXPECT_EQ(obstacle.at<uint8_t>(3, 30), 0);    // the room itself
  EXPECT_EQ(obstacle.at<uint8_t>(15, 10), 0);   // beside the desk
}

TEST(EnclosedPockets, LeavesAnOpenOutlineAndTheBorderAlone) {
  cv::Mat obstacle = MapWithOutlines();
  obstacle.at<uint8_t>(5, 10) = 0;  // a gap in the desk's outline
  // A pocket at the image border is no pocket: it may go on beyond the map.
  obstacle(cv::Rect(0, 0, 60, 1)).setTo(0);
  FillEnclosedPockets(100, &obstacle);
  EXPECT_EQ(obstacle.at<uint8_t>(9, 10), 0);
  EXPECT_EQ(obstacle.at<uint8_t>(3, 30), 0);
  EXPECT_EQ(obstacle.at<uint8_t>(25, 35), 255);  // the long ring is within 100
}

// Against OpenCV's labelling of the free cells (4-connected) and its boxes,
// on random clutter where pockets of every size and shape form.
TEST(EnclosedPockets, FillsWhatOpenCvsComponentsSay) {
  std::mt19937 random(7);
  for (int trial = 0; trial < 20; ++trial) {
    cv::Mat obstacle(90, 130, CV_8U);
    std::bernoulli_distribution wall(0.35 + 0.02 * trial);
    for (int r = 0; r < obstacle.rows; ++r) {
      for (int c = 0; c < obstacle.cols; ++c) obstacle.at<uint8_t>(r, c) = wall(random) ? 255 : 0;
    }
    const double max_pocket_px = 1 + trial % 7;
    cv::Mat labels, stats, centroids;
    cv::connectedComponentsWithStats(obstacle == 0, labels, stats, centroids, 4, CV_32S);
    cv::Mat expected = obstacle.clone();
    for (int r = 0; r < obstacle.rows; ++r) {
      for (int c = 0; c < obstacle.cols; ++c) {
        const int k = labels.at<int>(r, c);
        if (k == 0) continue;
        const int x = stats.at<int>(k, cv::CC_STAT_LEFT), y = stats.at<int>(k, cv::CC_STAT_TOP);
        const int w = stats.at<int>(k, cv::CC_STAT_WIDTH), h = stats.at<int>(k, cv::CC_STAT_HEIGHT);
        const bool border = x == 0 || y == 0 || x + w == obstacle.cols || y + h == obstacle.rows;
        if (!border && std::max(w, h) <= max_pocket_px) expected.at<uint8_t>(r, c) = 255;
      }
    }
    FillEnclosedPockets(max_pocket_px, &obstacle);
    ASSERT_EQ(cv::countNonZero(obstacle != expected), 0) << "trial " << trial;
  }
}

}  // namespace
}  // namespace areagraph

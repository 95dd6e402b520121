#include "stages/geometry/enclosed_pockets.h"

#include <gtest/gtest.h>

#include <opencv2/imgproc.hpp>

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

}  // namespace
}  // namespace areagraph

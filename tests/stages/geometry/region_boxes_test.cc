#include "stages/geometry/region_boxes.h"

#include <gtest/gtest.h>

#include <opencv2/imgproc.hpp>
#include <random>

namespace areagraph {
namespace {

// Holds LabelRegionsWithBoxes to cv::connectedComponentsWithStats, the
// library call it replaces: the same labels cell for cell and the same five
// statistics for every label that has cells.
void ExpectSameAsOpenCv(const cv::Mat& mask, int connectivity) {
  cv::Mat labels, stats;
  const int count = LabelRegionsWithBoxes(mask, connectivity, &labels, &stats);
  cv::Mat want_labels, want_stats, centroids;
  const int want_count = cv::connectedComponentsWithStats(mask, want_labels, want_stats, centroids,
                                                          connectivity, CV_32S);
  ASSERT_EQ(count, want_count);
  ASSERT_EQ(labels.type(), CV_32S);
  ASSERT_EQ(cv::countNonZero(labels != want_labels), 0);
  ASSERT_EQ(stats.rows, count);
  ASSERT_EQ(stats.type(), CV_32S);
  for (int label = 0; label < count; ++label) {
    if (want_stats.at<int>(label, cv::CC_STAT_AREA) == 0) {
      EXPECT_EQ(stats.at<int>(label, cv::CC_STAT_AREA), 0);
      continue;
    }
    for (int column = 0; column < cv::CC_STAT_MAX; ++column) {
      EXPECT_EQ(stats.at<int>(label, column), want_stats.at<int>(label, column))
          << "label " << label << " column " << column;
    }
  }
}

cv::Mat RandomMask(std::mt19937& random, int rows, int cols, double density) {
  cv::Mat mask(rows, cols, CV_8U);
  std::bernoulli_distribution set(density);
  for (int i = 0; i < rows * cols; ++i) mask.data[i] = set(random) ? 255 : 0;
  return mask;
}

TEST(RegionBoxes, EqualOpenCvsStatisticsOnRandomMasks) {
  std::mt19937 random(14);
  for (const double density : {0.05, 0.3, 0.5, 0.7, 0.95}) {
    for (const cv::Size size :
         {cv::Size(1, 1), cv::Size(1, 37), cv::Size(53, 1), cv::Size(64, 48), cv::Size(301, 177)}) {
      const cv::Mat mask = RandomMask(random, size.height, size.width, density);
      ExpectSameAsOpenCv(mask, 8);
      ExpectSameAsOpenCv(mask, 4);
    }
  }
}

TEST(RegionBoxes, EqualOpenCvsStatisticsOnAMapLikeMask) {
  // Walls around and across, a room with desks, a diagonal wall, an island
  // touching the border, and a large unknown outside.
  cv::Mat mask(400, 600, CV_8U, cv::Scalar(255));
  mask(cv::Rect(40, 30, 500, 330)).setTo(0);
  cv::rectangle(mask, cv::Rect(40, 30, 500, 330), cv::Scalar(255), 3);
  cv::line(mask, {290, 30}, {290, 200}, cv::Scalar(255), 4);
  cv::line(mask, {100, 360}, {400, 120}, cv::Scalar(255), 2);
  for (int k = 0; k < 12; ++k) {
    cv::rectangle(mask, cv::Rect(60 + 35 * k, 250 + (k % 3) * 20, 20, 10), cv::Scalar(255),
                  cv::FILLED);
  }
  cv::circle(mask, {599, 0}, 30, cv::Scalar(0), cv::FILLED);
  ExpectSameAsOpenCv(mask, 8);
  ExpectSameAsOpenCv(mask, 4);
  ExpectSameAsOpenCv(~mask, 8);
  ExpectSameAsOpenCv(~mask, 4);
}

TEST(RegionBoxes, AMaskWithoutBackground) {
  const cv::Mat mask(20, 30, CV_8U, cv::Scalar(255));
  cv::Mat labels, stats;
  ASSERT_EQ(LabelRegionsWithBoxes(mask, 8, &labels, &stats), 2);
  EXPECT_EQ(stats.at<int>(0, cv::CC_STAT_AREA), 0);
  EXPECT_EQ(stats.at<int>(1, cv::CC_STAT_LEFT), 0);
  EXPECT_EQ(stats.at<int>(1, cv::CC_STAT_TOP), 0);
  EXPECT_EQ(stats.at<int>(1, cv::CC_STAT_WIDTH), 30);
  EXPECT_EQ(stats.at<int>(1, cv::CC_STAT_HEIGHT), 20);
  EXPECT_EQ(stats.at<int>(1, cv::CC_STAT_AREA), 600);
}

// Labels outside 0 to count - 1 (ag-merge's raster marks cells of no area
// with -1) count for no box.
TEST(RegionBoxes, LabelBoxesSkipsLabelsOutsideTheCount) {
  cv::Mat labels(4, 6, CV_32S, cv::Scalar(-1));
  labels(cv::Rect(1, 1, 3, 2)).setTo(1);
  labels.at<int>(3, 5) = 7;
  const cv::Mat stats = LabelBoxes(labels, 3);
  ASSERT_EQ(stats.rows, 3);
  EXPECT_EQ(stats.at<int>(0, cv::CC_STAT_AREA), 0);
  EXPECT_EQ(stats.at<int>(1, cv::CC_STAT_LEFT), 1);
  EXPECT_EQ(stats.at<int>(1, cv::CC_STAT_TOP), 1);
  EXPECT_EQ(stats.at<int>(1, cv::CC_STAT_WIDTH), 3);
  EXPECT_EQ(stats.at<int>(1, cv::CC_STAT_HEIGHT), 2);
  EXPECT_EQ(stats.at<int>(1, cv::CC_STAT_AREA), 6);
  EXPECT_EQ(stats.at<int>(2, cv::CC_STAT_AREA), 0);
}

}  // namespace
}  // namespace areagraph

// Rasterizing area polygons by pixel centres.
#include "tools/export/area_label_image.h"

#include <gtest/gtest.h>

#include <opencv2/core.hpp>

#include "common/error.h"
#include "tests/tools/export/test_area_graph.h"

namespace areagraph {
namespace {

proto::Polygon PolygonOf(const std::vector<std::pair<double, double>>& corners) {
  proto::Polygon polygon;
  for (const auto& [x, y] : corners) {
    proto::Point2* point = polygon.mutable_outer()->add_points();
    point->set_x(x);
    point->set_y(y);
  }
  return polygon;
}

TEST(AreaLabelImage, LabelsAreIdPlusOneWithHolesLeftOut) {
  const cv::Mat labels = AreaLabelImage(testing::TwoRoomAreaGraph());
  ASSERT_EQ(labels.type(), CV_16U);
  EXPECT_EQ(labels.cols, 40);
  EXPECT_EQ(labels.rows, 20);
  EXPECT_EQ(cv::countNonZero(labels == 1), 100);
  EXPECT_EQ(cv::countNonZero(labels == 2), 96);
  EXPECT_EQ(cv::countNonZero(labels == 0), 40 * 20 - 196);
  EXPECT_EQ(labels.at<uint16_t>(2, 2), 1);    // first pixel inside area 0
  EXPECT_EQ(labels.at<uint16_t>(11, 11), 1);  // last one
  EXPECT_EQ(labels.at<uint16_t>(5, 12), 2);   // the shared edge's right side
  EXPECT_EQ(labels.at<uint16_t>(6, 16), 0);   // the hole
  EXPECT_EQ(labels.at<uint16_t>(12, 5), 0);   // below both
}

// Two triangles that split a square share its diagonal, which runs through
// pixel centres: each such pixel goes to exactly one of them.
TEST(AreaLabelImage, TilingPolygonsShareNoPixel) {
  cv::Mat upper(10, 10, CV_16U, cv::Scalar(0)), lower(10, 10, CV_16U, cv::Scalar(0));
  FillPolygonByPixelCentres(PolygonOf({{0, 0}, {10, 0}, {10, 10}}), 1, &upper);
  FillPolygonByPixelCentres(PolygonOf({{0, 0}, {10, 10}, {0, 10}}), 1, &lower);
  EXPECT_EQ(cv::countNonZero(upper & lower), 0);
  EXPECT_EQ(cv::countNonZero(upper | lower), 100);
  EXPECT_EQ(cv::countNonZero(upper), 55);  // the diagonal is its left edge, which is inclusive
}

// A square between pixel centres covers the pixels whose centres it holds,
// not the ones its outline merely touches (which cv::fillPoly would add).
TEST(AreaLabelImage, OnlyPixelCentresInsideCount) {
  cv::Mat image(20, 20, CV_16U, cv::Scalar(0));
  FillPolygonByPixelCentres(PolygonOf({{3.2, 3.2}, {8.7, 3.2}, {8.7, 6.9}, {3.2, 6.9}}), 7, &image);
  // Columns with centre in [3.2, 8.7): 3.5 .. 8.5 -> 3..8; rows 3.5 .. 6.5 -> 3..6.
  EXPECT_EQ(cv::countNonZero(image), 6 * 4);
  EXPECT_EQ(image.at<uint16_t>(3, 3), 7);
  EXPECT_EQ(image.at<uint16_t>(6, 8), 7);
  EXPECT_EQ(image.at<uint16_t>(7, 8), 0);
}

TEST(AreaLabelImage, PolygonsPastTheBorderAreClipped) {
  cv::Mat image(10, 10, CV_16U, cv::Scalar(0));
  FillPolygonByPixelCentres(PolygonOf({{-5, -5}, {15, -5}, {15, 15}, {-5, 15}}), 3, &image);
  EXPECT_EQ(cv::countNonZero(image == 3), 100);
}

TEST(AreaLabelImage, RejectsIdsThatDoNotFitSixteenBits) {
  proto::AreaGraph graph = testing::TwoRoomAreaGraph();
  graph.mutable_areas(1)->set_id(65535);
  EXPECT_THROW(AreaLabelImage(graph), InputError);
  graph.mutable_areas(1)->set_id(-1);
  EXPECT_THROW(AreaLabelImage(graph), InputError);
}

}  // namespace
}  // namespace areagraph

// Rings held packed (Ring.xy) read the same as rings of Point2 messages:
// points, area and raster, so prune and cut can write packed rings while
// format 1 artifacts in old stores still read.
#include "stages/geometry/ring_points.h"

#include <gtest/gtest.h>

#include <opencv2/core.hpp>

#include "stages/geometry/polygon_raster.h"
#include "stages/geometry/ring_area.h"

namespace areagraph {
namespace {

const PointList kLShape{{2, 2}, {30, 2}, {30, 12}, {12, 12}, {12, 28}, {2, 28}};

proto::Ring MessageRing(const PointList& points) {
  proto::Ring ring;
  for (const Eigen::Vector2d& p : points) {
    proto::Point2* point = ring.add_points();
    point->set_x(p.x());
    point->set_y(p.y());
  }
  return ring;
}

TEST(RingPointsTest, PackedAndMessageRingsReadTheSamePoints) {
  proto::Ring packed;
  SetPackedRing(kLShape, &packed);
  EXPECT_EQ(packed.points_size(), 0);
  EXPECT_EQ(packed.xy_size(), 2 * static_cast<int>(kLShape.size()));
  const proto::Ring message = MessageRing(kLShape);
  ASSERT_EQ(RingSize(packed), static_cast<int>(kLShape.size()));
  ASSERT_EQ(RingSize(message), static_cast<int>(kLShape.size()));
  EXPECT_EQ(RingPoints(packed), kLShape);
  EXPECT_EQ(RingPoints(message), kLShape);
  EXPECT_EQ(RingPoint(packed, 3), Eigen::Vector2d(12, 12));
}

TEST(RingPointsTest, SetPackedRingReplacesMessagePoints) {
  proto::Ring ring = MessageRing({{0, 0}, {1, 0}, {1, 1}});
  SetPackedRing(kLShape, &ring);
  EXPECT_EQ(ring.points_size(), 0);
  EXPECT_EQ(RingPoints(ring), kLShape);
  SetPackedRing({}, &ring);
  EXPECT_EQ(RingSize(ring), 0);
}

TEST(RingPointsTest, AreaAndRasterAgreeAcrossLayouts) {
  proto::Polygon packed;
  SetPackedRing(kLShape, packed.mutable_outer());
  proto::Polygon message;
  *message.mutable_outer() = MessageRing(kLShape);
  // 28 x 10 plus 10 x 16 pixels.
  EXPECT_DOUBLE_EQ(std::abs(TwiceSignedArea(packed.outer())), 2.0 * (28 * 10 + 10 * 16));
  EXPECT_DOUBLE_EQ(TwiceSignedArea(packed.outer()), TwiceSignedArea(message.outer()));
  const cv::Mat a = PolygonMask(packed, cv::Size(40, 40));
  const cv::Mat b = PolygonMask(message, cv::Size(40, 40));
  EXPECT_GT(cv::countNonZero(a), 28 * 10);
  EXPECT_EQ(cv::countNonZero(a != b), 0);
}

}  // namespace
}  // namespace areagraph

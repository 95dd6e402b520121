#include "stages/common/map_frame.h"

#include <gtest/gtest.h>

#include <cmath>

namespace areagraph {
namespace {

proto::MapFrame Frame(double yaw) {
  proto::MapFrame frame;
  frame.set_resolution_m(0.05);
  frame.set_origin_x_m(-10);
  frame.set_origin_y_m(-5);
  frame.set_origin_yaw_rad(yaw);
  frame.set_width_px(200);
  frame.set_height_px(100);
  return frame;
}

TEST(MapTransformTest, BottomLeftCornerIsTheOrigin) {
  const MapTransform transform(Frame(0));
  const Eigen::Vector2d origin = transform.PixelToWorld({0, 100});
  EXPECT_NEAR(origin.x(), -10, 1e-12);
  EXPECT_NEAR(origin.y(), -5, 1e-12);
  const Eigen::Vector2d top_right = transform.PixelToWorld({200, 0});
  EXPECT_NEAR(top_right.x(), 0, 1e-12);
  EXPECT_NEAR(top_right.y(), 0, 1e-12);
}

TEST(MapTransformTest, RoundTripWithYaw) {
  const MapTransform transform(Frame(M_PI / 2));
  const Eigen::Vector2d pixel(12.5, 40.5);
  const Eigen::Vector2d world = transform.PixelToWorld(pixel);
  EXPECT_TRUE(transform.WorldToPixel(world).isApprox(pixel, 1e-12));
  // Rotated a quarter turn: moving right in the image moves +y in the world.
  const Eigen::Vector2d step = transform.PixelToWorld(pixel + Eigen::Vector2d(20, 0)) - world;
  EXPECT_NEAR(step.x(), 0, 1e-12);
  EXPECT_NEAR(step.y(), 1.0, 1e-12);
}

}  // namespace
}  // namespace areagraph

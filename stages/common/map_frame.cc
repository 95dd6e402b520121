#include "stages/common/map_frame.h"

namespace areagraph {

MapTransform::MapTransform(const proto::MapFrame& frame) : resolution_m_(frame.resolution_m()) {
  // Pixel rows grow downwards, world y grows upwards: flip about the bottom edge.
  Eigen::Affine2d pixel_to_grid = Eigen::Affine2d::Identity();
  pixel_to_grid.linear() << resolution_m_, 0, 0, -resolution_m_;
  pixel_to_grid.translation() << 0, frame.height_px() * resolution_m_;
  pixel_to_world_ = Eigen::Translation2d(frame.origin_x_m(), frame.origin_y_m()) *
                    Eigen::Rotation2Dd(frame.origin_yaw_rad()) * pixel_to_grid;
}

Eigen::Vector2d MapTransform::PixelToWorld(const Eigen::Vector2d& pixel) const {
  return pixel_to_world_ * pixel;
}

Eigen::Vector2d MapTransform::WorldToPixel(const Eigen::Vector2d& world) const {
  return pixel_to_world_.inverse() * world;
}

}  // namespace areagraph

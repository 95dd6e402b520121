#pragma once

#include <Eigen/Geometry>

#include "proto/geometry.pb.h"

namespace areagraph {

// Converts between pixel coordinates (x right, y down, origin at the image's
// top-left corner) and world metres (ROS map_server frame: the origin pose is
// that of the image's bottom-left corner).
class MapTransform {
 public:
  explicit MapTransform(const proto::MapFrame& frame);

  Eigen::Vector2d PixelToWorld(const Eigen::Vector2d& pixel) const;
  Eigen::Vector2d WorldToPixel(const Eigen::Vector2d& world) const;
  double resolution_m() const { return resolution_m_; }

 private:
  double resolution_m_;
  Eigen::Affine2d pixel_to_world_;
};

}  // namespace areagraph

#pragma once

#include <google/protobuf/repeated_field.h>

#include <Eigen/Core>
#include <utility>

#include "proto/geometry.pb.h"

namespace areagraph {

// Area, first and second moments of a set of rings, summed over the rings'
// cv::moments (which counts each ring with positive orientation).
struct AreaMoments {
  double a = 0, x = 0, y = 0, xx = 0, yy = 0, xy = 0;

  void AddRing(const google::protobuf::RepeatedPtrField<proto::Point2>& ring);
  Eigen::Vector2d Centroid() const { return Eigen::Vector2d(x / a, y / a); }
  // The unit direction of the major axis and the ratio of the major to the
  // minor axis' variance (1 for a disk or a square).
  std::pair<Eigen::Vector2d, double> Axis() const;
};

}  // namespace areagraph

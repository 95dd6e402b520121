#pragma once

#include <Eigen/Core>
#include <utility>
#include <vector>

#include "proto/artifacts.pb.h"
#include "proto/geometry.pb.h"
#include "stages/merge/area_assignment.h"

namespace areagraph {

// Area, first and second moments of a set of rings, summed over the rings'
// cv::moments (which counts each ring with positive orientation).
struct AreaMoments {
  double a = 0, x = 0, y = 0, xx = 0, yy = 0, xy = 0;

  void AddRing(const proto::Ring& ring);
  Eigen::Vector2d Centroid() const { return Eigen::Vector2d(x / a, y / a); }
  // The unit direction of the major axis and the ratio of the major to the
  // minor axis' variance (1 for a disk or a square).
  std::pair<Eigen::Vector2d, double> Axis() const;
};

// Per area of `plan`: the moments of its edges' outer rings.
std::vector<AreaMoments> MomentsOfAreas(const proto::CutGraph& graph, const AreaPlan& plan);

}  // namespace areagraph

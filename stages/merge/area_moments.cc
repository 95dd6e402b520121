#include "stages/merge/area_moments.h"

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>
#include <vector>

#include "stages/geometry/ring_points.h"

namespace areagraph {

void AreaMoments::AddRing(const proto::Ring& ring) {
  std::vector<cv::Point2f> points;
  points.reserve(RingSize(ring));
  for (int i = 0; i < RingSize(ring); ++i) {
    const Eigen::Vector2d p = RingPoint(ring, i);
    points.emplace_back(p.x(), p.y());
  }
  const cv::Moments m = cv::moments(points);
  a += m.m00, x += m.m10, y += m.m01;
  xx += m.m20, yy += m.m02, xy += m.m11;
}

std::pair<Eigen::Vector2d, double> AreaMoments::Axis() const {
  const Eigen::Vector2d c = Centroid();
  const double sxx = xx / a - c.x() * c.x();
  const double syy = yy / a - c.y() * c.y();
  const double sxy = xy / a - c.x() * c.y();
  const double mean = (sxx + syy) / 2;
  const double spread = std::sqrt(std::max(0.0, (sxx - syy) * (sxx - syy) / 4 + sxy * sxy));
  const double major = mean + spread, minor = mean - spread;
  const double angle = 0.5 * std::atan2(2 * sxy, sxx - syy);
  return {Eigen::Vector2d(std::cos(angle), std::sin(angle)), minor > 0 ? major / minor : 1e9};
}

std::vector<AreaMoments> MomentsOfAreas(const proto::CutGraph& graph, const AreaPlan& plan) {
  std::vector<AreaMoments> moments(plan.areas.size());
  for (int e = 0; e < graph.edges_size(); ++e) {
    moments[plan.area_of_edge[e]].AddRing(graph.edges(e).polygon().outer());
  }
  return moments;
}

}  // namespace areagraph

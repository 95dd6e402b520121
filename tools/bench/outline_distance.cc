#include "tools/bench/outline_distance.h"

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "stages/geometry/ring_area.h"
#include "tools/export/area_polygons.h"

namespace areagraph {
namespace {

struct Segment {
  Eigen::Vector2d a, b;
};

void AddRing(const proto::Ring& ring, std::vector<Segment>* segments) {
  const int n = ring.points_size();
  for (int i = 0; i < n; ++i) {
    const proto::Point2& p = ring.points(i);
    const proto::Point2& q = ring.points((i + 1) % n);
    segments->push_back({{p.x(), p.y()}, {q.x(), q.y()}});
  }
}

std::vector<Segment> Boundary(const proto::Polygon& polygon, double ignore_holes_below_px2) {
  std::vector<Segment> segments;
  AddRing(polygon.outer(), &segments);
  for (const proto::Ring& hole : polygon.holes()) {
    if (std::abs(TwiceSignedArea(hole)) / 2 >= ignore_holes_below_px2) AddRing(hole, &segments);
  }
  return segments;
}

double Distance(const Eigen::Vector2d& p, const Segment& s) {
  const Eigen::Vector2d ab = s.b - s.a;
  const double length2 = ab.squaredNorm();
  const double t = length2 > 0 ? std::clamp((p - s.a).dot(ab) / length2, 0.0, 1.0) : 0.0;
  return (s.a + t * ab - p).norm();
}

// The farthest that a sample of `from` lies from `to`.
double OneSided(const std::vector<Segment>& from, const std::vector<Segment>& to) {
  double farthest = 0;
  for (const Segment& s : from) {
    const int steps = std::max(1, static_cast<int>(std::ceil((s.b - s.a).norm() / 0.25)));
    for (int i = 0; i < steps; ++i) {
      const Eigen::Vector2d p = s.a + (s.b - s.a) * (static_cast<double>(i) / steps);
      double nearest = std::numeric_limits<double>::infinity();
      for (const Segment& t : to) {
        nearest = std::min(nearest, Distance(p, t));
        if (nearest <= farthest) break;  // cannot raise the maximum
      }
      farthest = std::max(farthest, nearest);
    }
  }
  return farthest;
}

}  // namespace

double BoundaryDistancePx(const proto::Polygon& polygon, const proto::Polygon& reference,
                          double ignore_holes_below_px2) {
  const std::vector<Segment> mine = Boundary(polygon, 0);
  const std::vector<Segment> theirs = Boundary(reference, ignore_holes_below_px2);
  return std::max(OneSided(mine, theirs), OneSided(theirs, mine));
}

}  // namespace areagraph

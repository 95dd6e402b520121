#include "stages/cut/absorbed_polygons.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "stages/geometry/ring_points.h"

namespace areagraph {
namespace {

// Above this, a sum of squares cannot belong to a pair whose std::hypot is
// below `distance`: hypot is within an ulp, the sum within a few; 1e-12
// covers both.
double SquareBound(double distance) { return distance * distance * (1 + 1e-12); }

// The box around a list of points.
struct Box {
  double min_x = std::numeric_limits<double>::infinity(), min_y = min_x;
  double max_x = -min_x, max_y = -min_x;
  template <class Points>
  explicit Box(const Points& points) {
    for (const auto& p : points) {
      min_x = std::min(min_x, p.x()), max_x = std::max(max_x, p.x());
      min_y = std::min(min_y, p.y()), max_y = std::max(max_y, p.y());
    }
  }
};

// A sum of squares no pair of points from the two boxes goes below, as the
// search computes them: each gap between the boxes is at most the gap
// between two of their points, and rounding keeps that order.
double GapSquared(const Box& a, const Box& b) {
  const double dx = std::max({0.0, b.min_x - a.max_x, a.min_x - b.max_x});
  const double dy = std::max({0.0, b.min_y - a.max_y, a.min_y - b.max_y});
  return dx * dx + dy * dy;
}

}  // namespace

size_t NearestPiece(const std::vector<proto::GraphEdge>& pieces, const proto::Ring& ring) {
  size_t nearest = 0;
  double best = std::numeric_limits<double>::infinity();
  double bound = best;
  const PointList ring_points = RingPoints(ring);
  const Box ring_box(ring_points);
  for (size_t k = 0; k < pieces.size(); ++k) {
    // A piece whose box is farther than the bound has no pair to test.
    if (k > 0 && GapSquared(Box(pieces[k].path()), ring_box) > bound) continue;
    for (const proto::Point2& p : pieces[k].path()) {
      for (const Eigen::Vector2d& q : ring_points) {
        const double dx = p.x() - q.x(), dy = p.y() - q.y();
        // Most pairs end here, without the hypot (20 M instructions on a cluttered scan).
        if (dx * dx + dy * dy > bound) continue;
        const double d = std::hypot(dx, dy);
        if (d < best) {
          best = d, nearest = k;
          bound = SquareBound(best);
        }
      }
    }
  }
  return nearest;
}

}  // namespace areagraph

#include "stages/match/border_rings.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace areagraph {

BorderPoint ToBorderPoint(const proto::Point2& p) { return {p.x(), p.y()}; }

void SetBorderPoint(const BorderPoint& p, proto::Point2* out) {
  out->set_x(p.first);
  out->set_y(p.second);
}

std::vector<BorderRing> Rings(const proto::Polygon& polygon) {
  std::vector<BorderRing> rings;
  auto add = [&](const proto::Ring& ring) {
    BorderRing points;
    for (const proto::Point2& p : ring.points()) points.push_back(ToBorderPoint(p));
    while (points.size() > 1 && points.back() == points.front()) points.pop_back();
    rings.push_back(std::move(points));
  };
  add(polygon.outer());
  for (const proto::Ring& hole : polygon.holes()) add(hole);
  return rings;
}

proto::Polygon ToPolygon(const std::vector<BorderRing>& rings) {
  proto::Polygon polygon;
  for (size_t r = 0; r < rings.size(); ++r) {
    proto::Ring* ring = r == 0 ? polygon.mutable_outer() : polygon.add_holes();
    for (const BorderPoint& p : rings[r]) SetBorderPoint(p, ring->add_points());
  }
  return polygon;
}

double SquaredDistance(const BorderPoint& a, const BorderPoint& b) {
  const double dx = a.first - b.first, dy = a.second - b.second;
  return dx * dx + dy * dy;
}

double DistanceToRings(const BorderPoint& p, const std::vector<BorderRing>& rings) {
  double best = INFINITY;
  for (const BorderRing& ring : rings) {
    for (size_t i = 0; i < ring.size(); ++i) {
      const BorderPoint& u = ring[i];
      const BorderPoint& v = ring[(i + 1) % ring.size()];
      const double dx = v.first - u.first, dy = v.second - u.second;
      const double length2 = dx * dx + dy * dy;
      double t =
          length2 > 0 ? ((p.first - u.first) * dx + (p.second - u.second) * dy) / length2 : 0;
      t = std::clamp(t, 0.0, 1.0);
      best = std::min(best, SquaredDistance(p, {u.first + t * dx, u.second + t * dy}));
    }
  }
  return std::sqrt(best);
}

void AreaAndCentroid(const std::vector<BorderRing>& rings, double* area_m2,
                     proto::Point2* centroid) {
  double twice_area = 0, cx = 0, cy = 0;
  for (const BorderRing& ring : rings) {
    for (size_t i = 0; i < ring.size(); ++i) {
      const BorderPoint& p = ring[i];
      const BorderPoint& q = ring[(i + 1) % ring.size()];
      const double cross = p.first * q.second - q.first * p.second;
      twice_area += cross;
      cx += (p.first + q.first) * cross;
      cy += (p.second + q.second) * cross;
    }
  }
  *area_m2 = std::abs(twice_area) / 2;
  if (twice_area != 0) {
    centroid->set_x(cx / (3 * twice_area));
    centroid->set_y(cy / (3 * twice_area));
  }
}

std::set<BorderPoint> Vertices(const std::vector<BorderRing>& rings) {
  std::set<BorderPoint> vertices;
  for (const BorderRing& ring : rings) vertices.insert(ring.begin(), ring.end());
  return vertices;
}

bool ShareBorder(const proto::Polygon& a, const proto::Polygon& b) {
  std::set<std::pair<BorderPoint, BorderPoint>> edges;
  auto for_each_edge = [](const proto::Polygon& polygon, const auto& visit) {
    for (const BorderRing& ring : Rings(polygon)) {
      for (size_t i = 0; i < ring.size(); ++i) {
        const BorderPoint& p = ring[i];
        const BorderPoint& q = ring[(i + 1) % ring.size()];
        if (visit(std::make_pair(std::min(p, q), std::max(p, q)))) return true;
      }
    }
    return false;
  };
  for_each_edge(a, [&](const auto& edge) {
    edges.insert(edge);
    return false;
  });
  return for_each_edge(b, [&](const auto& edge) { return edges.count(edge) > 0; });
}

}  // namespace areagraph

#include "stages/match/polygon_union.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>
#include <vector>

#include "stages/geometry/ring_area.h"

namespace areagraph {
namespace {

using Point = std::pair<double, double>;
using Edge = std::pair<Point, Point>;

// The edges of every ring of `polygon`, in ring order; a closing point that
// repeats the first and zero-length edges are left out.
void AppendEdges(const proto::Polygon& polygon, std::vector<Edge>* edges) {
  auto add_ring = [&](const proto::Ring& ring) {
    std::vector<Point> points;
    for (const proto::Point2& p : ring.points()) {
      const Point point{p.x(), p.y()};
      if (points.empty() || points.back() != point) points.push_back(point);
    }
    while (points.size() > 1 && points.back() == points.front()) points.pop_back();
    if (points.size() < 3) return;
    for (size_t i = 0; i < points.size(); ++i) {
      edges->emplace_back(points[i], points[(i + 1) % points.size()]);
    }
  };
  add_ring(polygon.outer());
  for (const proto::Ring& hole : polygon.holes()) add_ring(hole);
}

// Twice the signed area (shoelace) of a closed ring of traced points.
double TwiceSignedArea(const std::vector<Point>& ring) {
  double sum = 0;
  for (size_t i = 0; i < ring.size(); ++i) {
    const Point& p = ring[i];
    const Point& q = ring[(i + 1) % ring.size()];
    sum += p.first * q.second - q.first * p.second;
  }
  return sum;
}

proto::Ring ToRing(const std::vector<Point>& points) {
  proto::Ring ring;
  for (const Point& p : points) {
    proto::Point2* point = ring.add_points();
    point->set_x(p.first);
    point->set_y(p.second);
  }
  return ring;
}

}  // namespace

bool UnionOfNeighbours(const proto::Polygon& a, const proto::Polygon& b, proto::Polygon* out) {
  std::vector<Edge> edges_a, edges_b;
  AppendEdges(a, &edges_a);
  AppendEdges(b, &edges_b);
  // b's edges by their reversed direction, to find the ones a holds too.
  std::multimap<Edge, size_t> reversed_b;
  for (size_t i = 0; i < edges_b.size(); ++i) {
    reversed_b.emplace(Edge{edges_b[i].second, edges_b[i].first}, i);
  }
  std::vector<bool> dropped_a(edges_a.size(), false), dropped_b(edges_b.size(), false);
  int shared = 0;
  for (size_t i = 0; i < edges_a.size(); ++i) {
    const auto found = reversed_b.find(edges_a[i]);
    if (found == reversed_b.end()) continue;
    dropped_a[i] = dropped_b[found->second] = true;
    reversed_b.erase(found);
    ++shared;
  }
  if (shared == 0) return false;

  std::vector<Edge> left;
  for (size_t i = 0; i < edges_a.size(); ++i) {
    if (!dropped_a[i]) left.push_back(edges_a[i]);
  }
  for (size_t i = 0; i < edges_b.size(); ++i) {
    if (!dropped_b[i]) left.push_back(edges_b[i]);
  }
  std::multimap<Point, size_t> outgoing;
  for (size_t i = 0; i < left.size(); ++i) outgoing.emplace(left[i].first, i);

  // Chain the remaining edges into closed rings.
  std::vector<std::vector<Point>> rings;
  std::vector<bool> used(left.size(), false);
  for (size_t start = 0; start < left.size(); ++start) {
    if (used[start]) continue;
    std::vector<Point> ring;
    size_t edge = start;
    while (true) {
      used[edge] = true;
      outgoing.erase(std::find_if(outgoing.lower_bound(left[edge].first),
                                  outgoing.upper_bound(left[edge].first),
                                  [&](const auto& entry) { return entry.second == edge; }));
      ring.push_back(left[edge].first);
      const Point& next = left[edge].second;
      if (next == left[start].first) break;
      const auto found = outgoing.find(next);
      if (found == outgoing.end()) return false;  // an open chain: borders did not match
      edge = found->second;
    }
    rings.push_back(std::move(ring));
  }

  const double outer_sign = TwiceSignedArea(a.outer()) >= 0 ? 1.0 : -1.0;
  proto::Polygon result;
  int outers = 0;
  for (const std::vector<Point>& ring : rings) {
    const double twice_area = TwiceSignedArea(ring);
    if (ring.size() < 3 || std::abs(twice_area) < 1e-12) continue;  // a slit of zero area
    if (twice_area * outer_sign > 0) {
      ++outers;
      *result.mutable_outer() = ToRing(ring);
    } else {
      *result.add_holes() = ToRing(ring);
    }
  }
  if (outers != 1) return false;
  *out = std::move(result);
  return true;
}

}  // namespace areagraph

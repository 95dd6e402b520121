#include "tools/route/free_space.h"

#include <algorithm>
#include <cmath>
#include <set>
#include <string>
#include <utility>

#include "common/error.h"
#include "stages/geometry/ring_area.h"
#include "stages/geometry/ring_points.h"

namespace areagraph {
namespace {

constexpr double kPi = 3.14159265358979323846;
// Directions closer than this (sine of the angle) count as parallel.
constexpr double kAngleTolerance = 1e-9;

double Cross(const Vec2& a, const Vec2& b) { return a.x() * b.y() - a.y() * b.x(); }

double DistanceToSegment(const Vec2& point, const Vec2& a, const Vec2& b) {
  const Vec2 ab = b - a;
  const double length2 = ab.squaredNorm();
  const double t = length2 > 0 ? std::clamp((point - a).dot(ab) / length2, 0.0, 1.0) : 0.0;
  return (a + t * ab - point).norm();
}

// Points compared bit for bit: the areas share their border vertices exactly.
using PointKey = std::pair<double, double>;
PointKey KeyOf(const Vec2& point) { return {point.x(), point.y()}; }
std::pair<PointKey, PointKey> EdgeKey(const Vec2& a, const Vec2& b) {
  return std::minmax(KeyOf(a), KeyOf(b));
}

// The area's rings, outer first, each running with the area on its left,
// without repeated points; rings of fewer than three points are dropped.
std::vector<std::vector<Vec2>> AreaRings(const proto::Area& area) {
  const proto::Polygon& polygon = area.polygon_m();
  if (RingSize(polygon.outer()) < 3) {
    throw InputError("area " + std::to_string(area.id()) +
                     " has no polygon in metres; make the Area Graph again with this areagraph");
  }
  std::vector<std::vector<Vec2>> rings;
  auto add = [&](const proto::Ring& ring, bool counter_clockwise) {
    std::vector<Vec2> points;
    for (int i = 0; i < RingSize(ring); ++i) {
      const Vec2 point = RingPoint(ring, i);
      if (!point.allFinite()) {
        throw InputError("area " + std::to_string(area.id()) +
                         " has a coordinate that is not a finite number");
      }
      if (points.empty() || point != points.back()) points.push_back(point);
    }
    while (points.size() > 1 && points.front() == points.back()) points.pop_back();
    if (points.size() < 3) return;
    if ((TwiceSignedArea(ring) > 0) != counter_clockwise)
      std::reverse(points.begin(), points.end());
    rings.push_back(std::move(points));
  };
  add(polygon.outer(), true);
  for (const proto::Ring& hole : polygon.holes()) add(hole, false);
  return rings;
}

// Whether `direction` points into one of the vertex's wedges (strictly).
bool WedgeHolds(const std::vector<OutlineVertex>& vertices, const OutlineVertex& vertex,
                const Vec2& direction) {
  for (const CornerWedge& wedge : vertex.wedges) {
    const Vec2 next = vertices[wedge.next].at - vertex.at;
    double angle = std::atan2(Cross(next, direction), next.dot(direction));
    if (angle < 0) angle += 2 * kPi;
    if (angle > kAngleTolerance && angle < wedge.angle - kAngleTolerance) return true;
  }
  return false;
}

// Whether a segment along `unit` through `vertex` crosses a wall there: walls
// on both of its sides, or, where it runs along a wall, no side that is both
// clear of walls and inside an area.
bool CrossesAtVertex(const std::vector<OutlineVertex>& vertices, const OutlineVertex& vertex,
                     const Vec2& unit) {
  bool left = false, right = false, along = false;
  for (const Vec2& wall : vertex.wall_directions) {
    const double side = Cross(unit, wall.normalized());
    if (side > kAngleTolerance) {
      left = true;
    } else if (side < -kAngleTolerance) {
      right = true;
    } else {
      along = true;
    }
  }
  if (!along) return left && right;
  const Vec2 left_normal(-unit.y(), unit.x());
  if (!left && WedgeHolds(vertices, vertex, left_normal)) return false;
  if (!right && WedgeHolds(vertices, vertex, -left_normal)) return false;
  return true;
}

}  // namespace

FreeSpace::FreeSpace(const proto::AreaGraph& graph) {
  std::set<std::pair<PointKey, PointKey>> passage_edges;
  for (const proto::Passage& passage : graph.passages()) {
    for (int i = 0; i + 1 < passage.border_m_size(); ++i) {
      const proto::Point2& a = passage.border_m(i);
      const proto::Point2& b = passage.border_m(i + 1);
      passage_edges.insert(EdgeKey(Vec2(a.x(), a.y()), Vec2(b.x(), b.y())));
    }
  }
  auto vertex_of = [&](const Vec2& point) {
    const auto [it, added] = vertex_ids_.emplace(KeyOf(point), static_cast<int>(vertices_.size()));
    if (added) vertices_.push_back(OutlineVertex{point, {}, {}});
    return it->second;
  };
  std::vector<Eigen::AlignedBox2d> edge_boxes;
  for (int area = 0; area < graph.areas_size(); ++area) {
    area_rings_.push_back(AreaRings(graph.areas(area)));
    Eigen::AlignedBox2d box;
    for (const std::vector<Vec2>& ring : area_rings_.back()) {
      const int n = static_cast<int>(ring.size());
      for (int k = 0; k < n; ++k) {
        const Vec2& at = ring[k];
        const Vec2& next = ring[(k + 1) % n];
        const Vec2& previous = ring[(k + n - 1) % n];
        box.extend(at);
        OutlineEdge edge{at,
                         next,
                         area,
                         vertex_of(at),
                         vertex_of(next),
                         passage_edges.count(EdgeKey(at, next)) == 0};
        CornerWedge wedge;
        wedge.area = area;
        wedge.next = edge.vertex_b;
        wedge.previous = vertex_of(previous);
        wedge.angle = std::atan2(Cross(next - at, previous - at), (next - at).dot(previous - at));
        if (wedge.angle <= 0) wedge.angle += 2 * kPi;
        wedge.next_is_wall = edge.wall;
        wedge.previous_is_wall = passage_edges.count(EdgeKey(previous, at)) == 0;
        vertices_[edge.vertex_a].wedges.push_back(wedge);
        if (edge.wall) {
          vertices_[edge.vertex_a].wall_directions.push_back(next - at);
          vertices_[edge.vertex_b].wall_directions.push_back(at - next);
        }
        edge_boxes.emplace_back(at.cwiseMin(next), at.cwiseMax(next));
        edges_.push_back(edge);
      }
    }
    area_boxes_.push_back(box);
  }
  // About two cells per edge over the map's extent.
  Eigen::AlignedBox2d bounds;
  for (const Eigen::AlignedBox2d& box : area_boxes_) bounds.extend(box);
  const double extent = bounds.isEmpty() ? 1.0 : bounds.volume();
  const double cell = std::sqrt(extent / std::max<size_t>(1, 2 * edges_.size()));
  edge_cells_ = CellIndex(edge_boxes, cell, 2 * kRouteTolerance);
  area_cells_ = CellIndex(area_boxes_, 4 * cell, 2 * kRouteTolerance);
}

int FreeSpace::VertexAt(const Vec2& point) const {
  const auto found = vertex_ids_.find(KeyOf(point));
  return found == vertex_ids_.end() ? -1 : found->second;
}

bool FreeSpace::InsideArea(int area, const Vec2& point) const {
  bool inside = false;
  for (const std::vector<Vec2>& ring : area_rings_[area]) {
    const size_t n = ring.size();
    for (size_t i = 0, j = n - 1; i < n; j = i++) {
      const Vec2& a = ring[i];
      const Vec2& b = ring[j];
      if ((a.y() > point.y()) != (b.y() > point.y()) &&
          point.x() < (b.x() - a.x()) * (point.y() - a.y()) / (b.y() - a.y()) + a.x()) {
        inside = !inside;
      }
    }
  }
  return inside;
}

int FreeSpace::AreaAt(const Vec2& point) const {
  int found = -1;
  area_cells_.ForEachAt(point, [&](int area) {
    if (found < 0 && area_boxes_[area].exteriorDistance(point) <= kRouteTolerance &&
        InsideArea(area, point)) {
      found = area;
    }
  });
  if (found >= 0) return found;
  double nearest = kRouteTolerance;
  edge_cells_.ForEachAt(point, [&](int e) {
    const double distance = DistanceToSegment(point, edges_[e].a, edges_[e].b);
    if (distance <= nearest) {
      nearest = distance;
      found = edges_[e].area;
    }
  });
  return found;
}

bool FreeSpace::Contacts(const Vec2& from, const Vec2& to, bool walls_only,
                         std::vector<double>* contacts) const {
  const Vec2 d = to - from;
  const double length = d.norm();
  if (length <= kRouteTolerance) return true;
  const Vec2 unit = d / length;
  const double t_tolerance = kRouteTolerance / length;
  return edge_cells_.ForEachAlong(from, to, [&](int e) {
    const OutlineEdge& edge = edges_[e];
    if (walls_only && !edge.wall) return true;
    const double side_a = Cross(unit, edge.a - from);
    const double side_b = Cross(unit, edge.b - from);
    for (const auto& [end, side, vertex] :
         {std::tuple(edge.a, side_a, edge.vertex_a), std::tuple(edge.b, side_b, edge.vertex_b)}) {
      if (std::abs(side) > kRouteTolerance) continue;
      const double t = (end - from).dot(unit) / length;
      if (t <= t_tolerance || t >= 1 - t_tolerance) continue;
      contacts->push_back(t);
      if (walls_only && CrossesAtVertex(vertices_, vertices_[vertex], unit)) return false;
    }
    if ((side_a > kRouteTolerance && side_b < -kRouteTolerance) ||
        (side_a < -kRouteTolerance && side_b > kRouteTolerance)) {
      const Vec2 wall_unit = (edge.b - edge.a).normalized();
      const double side_from = Cross(wall_unit, from - edge.a);
      const double side_to = Cross(wall_unit, to - edge.a);
      if ((side_from > kRouteTolerance && side_to < -kRouteTolerance) ||
          (side_from < -kRouteTolerance && side_to > kRouteTolerance)) {
        if (walls_only) return false;
        contacts->push_back(side_from / (side_from - side_to));
      }
    }
    return true;
  });
}

bool FreeSpace::SegmentIsFree(const Vec2& from, const Vec2& to) const {
  std::vector<double> contacts{0.0, 1.0};
  if (!Contacts(from, to, /*walls_only=*/true, &contacts)) return false;
  std::sort(contacts.begin(), contacts.end());
  const double t_tolerance = kRouteTolerance / std::max((to - from).norm(), kRouteTolerance);
  for (size_t i = 0; i + 1 < contacts.size(); ++i) {
    if (contacts[i + 1] - contacts[i] <= t_tolerance) continue;
    const double middle = (contacts[i] + contacts[i + 1]) / 2;
    if (AreaAt(from + middle * (to - from)) < 0) return false;
  }
  return true;
}

std::optional<Vec2> FreeSpace::NearestPoint(const Vec2& point, double max_distance) const {
  if (AreaAt(point) >= 0) return point;
  std::optional<Vec2> nearest;
  double best = max_distance;
  const Vec2 reach = Vec2::Constant(max_distance);
  edge_cells_.ForEachInBox(Eigen::AlignedBox2d(point - reach, point + reach), [&](int e) {
    const OutlineEdge& edge = edges_[e];
    const Vec2 ab = edge.b - edge.a;
    const double t = std::clamp((point - edge.a).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
    const Vec2 on_edge = edge.a + t * ab;
    const double distance = (on_edge - point).norm();
    if (distance <= best) {
      best = distance;
      nearest = on_edge;
    }
  });
  return nearest;
}

void FreeSpace::AppendAreasAlong(const Vec2& from, const Vec2& to,
                                 std::vector<AreaVisit>* visits) const {
  std::vector<double> contacts{0.0, 1.0};
  Contacts(from, to, /*walls_only=*/false, &contacts);
  std::sort(contacts.begin(), contacts.end());
  for (size_t i = 0; i + 1 < contacts.size(); ++i) {
    if (contacts[i + 1] - contacts[i] <= 1e-12) continue;
    const int area = AreaAt(from + (contacts[i] + contacts[i + 1]) / 2 * (to - from));
    if (area >= 0 && (visits->empty() || visits->back().area != area)) {
      visits->push_back({area, from + contacts[i] * (to - from)});
    }
  }
}

}  // namespace areagraph

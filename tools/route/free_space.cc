#include "tools/route/free_space.h"

#include <algorithm>
#include <cmath>
#include <set>
#include <string>
#include <utility>

#include "common/error.h"
#include "stages/geometry/ring_area.h"
#include "stages/geometry/ring_points.h"
#include "tools/route/vertex_passage.h"

namespace areagraph {
namespace {

constexpr double kPi = 3.14159265358979323846;

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
  for (const proto::Area& area : graph.areas()) area_rings_.push_back(AreaRings(area));
  // An edge opens only where a passage's border lies on the outlines of both
  // areas; anywhere else, and on one outline only, it is a wall.
  std::map<std::pair<PointKey, PointKey>, std::set<int>> passage_edge_areas;
  for (size_t area = 0; area < area_rings_.size(); ++area) {
    for (const std::vector<Vec2>& ring : area_rings_[area]) {
      for (size_t k = 0; k < ring.size(); ++k) {
        const auto key = EdgeKey(ring[k], ring[(k + 1) % ring.size()]);
        if (passage_edges.count(key)) passage_edge_areas[key].insert(static_cast<int>(area));
      }
    }
  }
  auto is_wall = [&](const Vec2& a, const Vec2& b) {
    const auto found = passage_edge_areas.find(EdgeKey(a, b));
    return found == passage_edge_areas.end() || found->second.size() < 2;
  };
  auto vertex_of = [&](const Vec2& point) {
    const auto [it, added] = vertex_ids_.emplace(KeyOf(point), static_cast<int>(vertices_.size()));
    if (added) vertices_.push_back(OutlineVertex{point, {}, {}});
    return it->second;
  };
  std::vector<Eigen::AlignedBox2d> edge_boxes;
  for (int area = 0; area < graph.areas_size(); ++area) {
    Eigen::AlignedBox2d box;
    for (const std::vector<Vec2>& ring : area_rings_[area]) {
      const int n = static_cast<int>(ring.size());
      for (int k = 0; k < n; ++k) {
        const Vec2& at = ring[k];
        const Vec2& next = ring[(k + 1) % n];
        const Vec2& previous = ring[(k + n - 1) % n];
        box.extend(at);
        OutlineEdge edge{at, next, area, vertex_of(at), vertex_of(next), is_wall(at, next)};
        CornerWedge wedge;
        wedge.area = area;
        wedge.next = edge.vertex_b;
        wedge.previous = vertex_of(previous);
        wedge.angle = std::atan2(Cross(next - at, previous - at), (next - at).dot(previous - at));
        if (wedge.angle <= 0) wedge.angle += 2 * kPi;
        wedge.next_is_wall = edge.wall;
        wedge.previous_is_wall = is_wall(previous, at);
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
  // Each wall once (a wall between two areas is an edge of both), for the
  // segment test; an edge that is no wall gets an empty box there.
  std::set<std::pair<int, int>> walls;
  for (size_t e = 0; e < edges_.size(); ++e) {
    if (!edges_[e].wall ||
        !walls.insert(std::minmax(edges_[e].vertex_a, edges_[e].vertex_b)).second) {
      edge_boxes[e] = Eigen::AlignedBox2d();
    }
  }
  wall_cells_ = CellIndex(edge_boxes, cell, 2 * kRouteTolerance);
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
                         std::vector<Contact>* contacts) const {
  const Vec2 d = to - from;
  const double length = d.norm();
  if (length <= kRouteTolerance) return true;
  const Vec2 unit = d / length;
  const double t_tolerance = kRouteTolerance / length;
  const CellIndex& index = walls_only ? wall_cells_ : edge_cells_;
  return index.ForEachAlong(from, to, [&](int e) {
    const OutlineEdge& edge = edges_[e];
    const double side_a = Cross(unit, edge.a - from);
    const double side_b = Cross(unit, edge.b - from);
    // Most edges lie wholly on one side of the line.
    if ((side_a > kRouteTolerance && side_b > kRouteTolerance) ||
        (side_a < -kRouteTolerance && side_b < -kRouteTolerance)) {
      return true;
    }
    for (const int vertex : {edge.vertex_a, edge.vertex_b}) {
      const Vec2& end = vertices_[vertex].at;
      if (std::abs(vertex == edge.vertex_a ? side_a : side_b) > kRouteTolerance) continue;
      const double t = (end - from).dot(unit) / length;
      if (t > t_tolerance && t < 1 - t_tolerance) contacts->push_back({t, vertex});
    }
    if ((side_a > kRouteTolerance && side_b < -kRouteTolerance) ||
        (side_a < -kRouteTolerance && side_b > kRouteTolerance)) {
      const Vec2 wall_unit = (edge.b - edge.a).normalized();
      const double side_from = Cross(wall_unit, from - edge.a);
      const double side_to = Cross(wall_unit, to - edge.a);
      if ((side_from > kRouteTolerance && side_to < -kRouteTolerance) ||
          (side_from < -kRouteTolerance && side_to > kRouteTolerance)) {
        if (walls_only) return false;
        contacts->push_back({side_from / (side_from - side_to), -1});
      }
    }
    return true;
  });
}

bool FreeSpace::WallsLetThrough(const Vec2& from, const Vec2& to,
                                const std::vector<Contact>& contacts) const {
  const Vec2 unit = (to - from).normalized();
  // Along a wall the line keeps to one side of it: the banks still open.
  bool along = false;
  int banks = kLeftBank | kRightBank;
  for (size_t i = 0; i < contacts.size(); ++i) {
    if (i > 0 && contacts[i].vertex == contacts[i - 1].vertex) continue;
    const VertexPassage passage = PassThrough(vertices_, vertices_[contacts[i].vertex], unit);
    if (!passage.behind && !passage.ahead) {
      if (passage.crosses) return false;
      along = false;
      continue;
    }
    int open = passage.banks;
    if (passage.behind && along) open &= banks;
    if (passage.behind && i == 0) {
      // The wall began where the segment does.
      const int start = VertexAt(from);
      if (start >= 0) open &= PassThrough(vertices_, vertices_[start], unit).banks;
    }
    if (open == 0) return false;
    along = passage.ahead;
    banks = open;
  }
  if (along) {
    const int end = VertexAt(to);
    if (end >= 0 && (PassThrough(vertices_, vertices_[end], unit).banks & banks) == 0) return false;
  }
  return true;
}

bool FreeSpace::LeavesInto(int vertex, const Vec2& direction) const {
  return WedgeHolds(vertices_, vertices_[vertex], direction);
}

bool FreeSpace::StrictlyInside(const Vec2& point) const {
  bool near_edge = false;
  edge_cells_.ForEachAt(point, [&](int e) {
    near_edge = near_edge || DistanceToSegment(point, edges_[e].a, edges_[e].b) <= kRouteTolerance;
  });
  if (near_edge) return false;
  bool inside = false;
  area_cells_.ForEachAt(point, [&](int area) { inside = inside || InsideArea(area, point); });
  return inside;
}

bool FreeSpace::SegmentIsFree(const Vec2& from, const Vec2& to, bool starts_inside) const {
  std::vector<Contact> contacts;
  if (!Contacts(from, to, /*walls_only=*/true, &contacts)) return false;
  std::sort(contacts.begin(), contacts.end(), [](const Contact& a, const Contact& b) {
    return a.t < b.t || (a.t == b.t && a.vertex < b.vertex);
  });
  if (!WallsLetThrough(from, to, contacts)) return false;
  // Crossing no wall, a segment that starts inside stays inside.
  if (starts_inside) return true;
  const double t_tolerance = kRouteTolerance / std::max((to - from).norm(), kRouteTolerance);
  double last = 0;
  for (size_t i = 0; i <= contacts.size(); ++i) {
    const double next = i < contacts.size() ? contacts[i].t : 1.0;
    if (next - last <= t_tolerance) continue;
    if (AreaAt(from + (last + next) / 2 * (to - from)) < 0) return false;
    last = next;
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
  std::vector<Contact> contacts{{0.0, -1}, {1.0, -1}};
  Contacts(from, to, /*walls_only=*/false, &contacts);
  std::sort(contacts.begin(), contacts.end(),
            [](const Contact& a, const Contact& b) { return a.t < b.t; });
  for (size_t i = 0; i + 1 < contacts.size(); ++i) {
    const double t0 = contacts[i].t, t1 = contacts[i + 1].t;
    if (t1 - t0 <= 1e-12) continue;
    const int area = AreaAt(from + (t0 + t1) / 2 * (to - from));
    if (area >= 0 && (visits->empty() || visits->back().area != area)) {
      visits->push_back({area, from + t0 * (to - from)});
    }
  }
}

}  // namespace areagraph

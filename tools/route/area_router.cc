#include "tools/route/area_router.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <queue>
#include <tuple>

#include "common/error.h"
#include "common/text.h"

namespace areagraph {
namespace {

constexpr double kHalfTurn = 3.14159265358979323846;
constexpr double kInfinity = std::numeric_limits<double>::infinity();

double Cross(const Vec2& a, const Vec2& b) { return a.x() * b.y() - a.y() * b.x(); }

double DistanceToPolyline(const Vec2& point, const std::vector<Vec2>& line) {
  double nearest = kInfinity;
  for (size_t i = 0; i + 1 < line.size(); ++i) {
    const Vec2 ab = line[i + 1] - line[i];
    const double length2 = ab.squaredNorm();
    const double t = length2 > 0 ? std::clamp((point - line[i]).dot(ab) / length2, 0.0, 1.0) : 0.0;
    nearest = std::min(nearest, (line[i] + t * ab - point).norm());
  }
  return nearest;
}

std::string PointText(const Vec2& point) {
  return "(" + FormatNumber(point.x()) + ", " + FormatNumber(point.y()) + ")";
}

// Whether segments ab and cd share a point (touching counts).
bool SegmentsMeet(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d) {
  constexpr double kTouch = 1e-9;
  const double abc = Cross(b - a, c - a), abd = Cross(b - a, d - a);
  const double cda = Cross(d - c, a - c), cdb = Cross(d - c, b - c);
  if (((abc > kTouch && abd > kTouch) || (abc < -kTouch && abd < -kTouch)) ||
      ((cda > kTouch && cdb > kTouch) || (cda < -kTouch && cdb < -kTouch))) {
    return false;
  }
  // On one line: the two spans must overlap.
  const Vec2 axis = b - a;
  if (std::abs(abc) <= kTouch && std::abs(abd) <= kTouch) {
    const double length2 = std::max(axis.squaredNorm(), kTouch);
    const double tc = (c - a).dot(axis) / length2, td = (d - a).dot(axis) / length2;
    return std::max(tc, td) >= -kTouch && std::min(tc, td) <= 1 + kTouch;
  }
  return true;
}

int Root(std::vector<int>& parents, int item) {
  while (parents[item] != item) item = parents[item] = parents[parents[item]];
  return item;
}

}  // namespace

AreaRouter::AreaRouter(const proto::AreaGraph& graph, const RouteSettings& settings)
    : settings_(settings), space_(graph) {
  const int areas = graph.areas_size();
  area_neighbours_.resize(areas);
  area_passages_.resize(areas);
  component_.resize(areas);
  std::iota(component_.begin(), component_.end(), 0);
  for (int p = 0; p < graph.passages_size(); ++p) {
    const proto::Passage& passage = graph.passages(p);
    PassageLine line{passage.area_a(), passage.area_b(), {}};
    if (line.area_a < 0 || line.area_a >= areas || line.area_b < 0 || line.area_b >= areas) {
      throw InputError("passage " + std::to_string(passage.id()) + " names an area (" +
                       std::to_string(line.area_a) + " or " + std::to_string(line.area_b) +
                       ") that the graph does not have");
    }
    // A passage without a shared border (older graphs) says nothing of where
    // to cross, so routes do not cross it.
    if (passage.border_m_size() >= 2 && line.area_a != line.area_b) {
      for (const proto::Point2& point : passage.border_m())
        line.border.emplace_back(point.x(), point.y());
      area_neighbours_[line.area_a].push_back(line.area_b);
      area_neighbours_[line.area_b].push_back(line.area_a);
      area_passages_[line.area_a].push_back(p);
      area_passages_[line.area_b].push_back(p);
      component_[Root(component_, line.area_a)] = Root(component_, line.area_b);
    }
    passages_.push_back(std::move(line));
  }
  for (int area = 0; area < areas; ++area) component_[area] = Root(component_, area);
  FindCorners(graph);
  LinkCorners();
}

void AreaRouter::FindCorners(const proto::AreaGraph& graph) {
  const std::vector<OutlineVertex>& vertices = space_.vertices();
  std::vector<int> corner_of_vertex(vertices.size(), -1);
  auto wedge_areas = [](const OutlineVertex& vertex) {
    std::vector<int> areas;
    for (const CornerWedge& wedge : vertex.wedges) areas.push_back(wedge.area);
    std::sort(areas.begin(), areas.end());
    areas.erase(std::unique(areas.begin(), areas.end()), areas.end());
    return areas;
  };
  for (size_t v = 0; v < vertices.size(); ++v) {
    const OutlineVertex& vertex = vertices[v];
    // A stretch of free space around the vertex runs from a wall through the
    // wedges of the areas that meet there, across passage borders, to a wall.
    for (const CornerWedge& first : vertex.wedges) {
      if (!first.next_is_wall) continue;
      double angle = first.angle;
      const CornerWedge* last = &first;
      for (size_t steps = 0; !last->previous_is_wall && steps < vertex.wedges.size(); ++steps) {
        const CornerWedge* following = nullptr;
        for (const CornerWedge& wedge : vertex.wedges) {
          if (&wedge != last && wedge.next == last->previous) following = &wedge;
        }
        if (following == nullptr) break;
        angle += following->angle;
        last = following;
      }
      if (angle > kHalfTurn + 1e-9) {
        corner_of_vertex[v] = static_cast<int>(corners_.size());
        corners_.push_back({vertex.at, true, vertices[first.next].at - vertex.at,
                            vertices[last->previous].at - vertex.at, wedge_areas(vertex)});
        break;  // only one stretch can span more than half a turn
      }
    }
  }
  // The ends of every passage, so that each area's passages are linked
  // through the area even where no corner sticks out.
  for (const PassageLine& passage : passages_) {
    if (passage.border.empty()) continue;
    for (const Vec2& end : {passage.border.front(), passage.border.back()}) {
      const int v = space_.VertexAt(end);
      if (v >= 0 && corner_of_vertex[v] >= 0) continue;
      Corner corner{end, false, Vec2::Zero(), Vec2::Zero(), {passage.area_a, passage.area_b}};
      if (v >= 0) {
        corner.areas = wedge_areas(vertices[v]);
        corner_of_vertex[v] = static_cast<int>(corners_.size());
      }
      corners_.push_back(corner);
    }
  }
  area_corners_.assign(graph.areas_size(), {});
  for (size_t c = 0; c < corners_.size(); ++c) {
    for (const int area : corners_[c].areas) area_corners_[area].push_back(static_cast<int>(c));
  }
}

std::vector<int> AreaRouter::AreasWithin(int area, int hops) const {
  std::vector<int> reached{area};
  size_t ring_start = 0;
  for (int hop = 0; hop < hops; ++hop) {
    const size_t ring_end = reached.size();
    for (size_t i = ring_start; i < ring_end; ++i) {
      for (const int neighbour : area_neighbours_[reached[i]]) {
        if (std::find(reached.begin(), reached.end(), neighbour) == reached.end()) {
          reached.push_back(neighbour);
        }
      }
    }
    if (ring_end == reached.size()) break;
    ring_start = ring_end;
  }
  return reached;
}

bool AreaRouter::Tangent(const Corner& corner, const Vec2& direction) const {
  if (!corner.reflex) return true;
  // The walls' side of the corner (less than half a turn) must lie on one
  // side of the line, else the route could cut the corner short.
  const Vec2 unit = direction.normalized();
  const double a = Cross(unit, corner.wall_a.normalized());
  const double b = Cross(unit, corner.wall_b.normalized());
  return !((a > 1e-12 && b < -1e-12) || (a < -1e-12 && b > 1e-12));
}

void AreaRouter::LinkCorners() {
  std::vector<std::vector<int>> reach(area_corners_.size());
  for (size_t area = 0; area < reach.size(); ++area) {
    reach[area] = AreasWithin(static_cast<int>(area), settings_.link_hops);
  }
  std::vector<std::tuple<int, int, double>> links;
  std::vector<int> seen(corners_.size(), -1);
  for (int u = 0; u < corner_count(); ++u) {
    const Corner& from = corners_[u];
    for (const int area : from.areas) {
      for (const int other_area : reach[area]) {
        for (const int v : area_corners_[other_area]) {
          if (v <= u || seen[v] == u) continue;
          seen[v] = u;
          const Vec2 direction = corners_[v].at - from.at;
          if (!Tangent(from, direction) || !Tangent(corners_[v], direction)) continue;
          if (!space_.SegmentIsFree(from.at, corners_[v].at)) continue;
          links.emplace_back(u, v, direction.norm());
        }
      }
    }
  }
  link_offsets_.assign(corners_.size() + 1, 0);
  for (const auto& [u, v, length] : links) {
    ++link_offsets_[u + 1];
    ++link_offsets_[v + 1];
  }
  std::partial_sum(link_offsets_.begin(), link_offsets_.end(), link_offsets_.begin());
  link_targets_.resize(2 * links.size());
  link_lengths_.resize(2 * links.size());
  std::vector<int> filled(link_offsets_.begin(), link_offsets_.end() - 1);
  for (const auto& [u, v, length] : links) {
    link_targets_[filled[u]] = v;
    link_lengths_[filled[u]++] = length;
    link_targets_[filled[v]] = u;
    link_lengths_[filled[v]++] = length;
  }
}

std::vector<std::pair<int, int>> AreaRouter::Links() const {
  std::vector<std::pair<int, int>> links;
  for (int u = 0; u < corner_count(); ++u) {
    for (int i = link_offsets_[u]; i < link_offsets_[u + 1]; ++i) {
      if (u < link_targets_[i]) links.emplace_back(u, link_targets_[i]);
    }
  }
  return links;
}

std::vector<int> AreaRouter::EndCandidates(int area) const {
  std::vector<int> candidates;
  for (const int other_area : AreasWithin(area, settings_.end_hops)) {
    candidates.insert(candidates.end(), area_corners_[other_area].begin(),
                      area_corners_[other_area].end());
  }
  std::sort(candidates.begin(), candidates.end());
  candidates.erase(std::unique(candidates.begin(), candidates.end()), candidates.end());
  return candidates;
}

bool AreaRouter::LeavesThroughAPassage(const Vec2& point, int area, const Vec2& to) const {
  for (const int p : area_passages_[area]) {
    const std::vector<Vec2>& border = passages_[p].border;
    for (size_t i = 0; i + 1 < border.size(); ++i) {
      if (SegmentsMeet(point, to, border[i], border[i + 1])) return true;
    }
  }
  return false;
}

std::vector<std::pair<int, double>> AreaRouter::VisibleCorners(const Vec2& point, int area) const {
  std::vector<std::pair<int, double>> visible;
  for (const int c : EndCandidates(area)) {
    const Corner& corner = corners_[c];
    const Vec2 direction = corner.at - point;
    if (!Tangent(corner, direction)) continue;
    // Everything of the area's outline but its passages is wall: a line to
    // a corner of another area must cross one of them (a cheap test first).
    const bool own =
        std::find(corner.areas.begin(), corner.areas.end(), area) != corner.areas.end();
    if (!own && !LeavesThroughAPassage(point, area, corner.at)) continue;
    if (space_.SegmentIsFree(point, corner.at)) visible.emplace_back(c, direction.norm());
  }
  return visible;
}

std::optional<std::vector<Vec2>> AreaRouter::ShortestPolyline(const Vec2& start, int start_area,
                                                              const Vec2& goal,
                                                              int goal_area) const {
  if (space_.SegmentIsFree(start, goal)) return std::vector<Vec2>{start, goal};
  const int goal_node = corner_count();
  std::vector<double> to_goal(corners_.size(), kInfinity);
  for (const auto& [c, length] : VisibleCorners(goal, goal_area)) to_goal[c] = length;
  // A* from the start to the goal node over the corners, with the straight
  // distance to the goal as the (consistent) estimate.
  std::vector<double> best(corners_.size() + 1, kInfinity);
  std::vector<int> parent(corners_.size() + 1, -1);
  std::vector<char> done(corners_.size() + 1, 0);
  using Entry = std::pair<double, int>;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<>> open;
  auto reach = [&](int node, double length, int from) {
    if (length >= best[node]) return;
    best[node] = length;
    parent[node] = from;
    const double estimate = node == goal_node ? 0 : (goal - corners_[node].at).norm();
    open.emplace(length + estimate, node);
  };
  for (const auto& [c, length] : VisibleCorners(start, start_area)) reach(c, length, -1);
  while (!open.empty()) {
    const int node = open.top().second;
    open.pop();
    if (done[node]) continue;
    done[node] = 1;
    if (node == goal_node) break;
    if (to_goal[node] < kInfinity) reach(goal_node, best[node] + to_goal[node], node);
    for (int i = link_offsets_[node]; i < link_offsets_[node + 1]; ++i) {
      if (!done[link_targets_[i]]) reach(link_targets_[i], best[node] + link_lengths_[i], node);
    }
  }
  if (!done[goal_node]) return std::nullopt;
  std::vector<Vec2> polyline{goal};
  for (int node = parent[goal_node]; node >= 0; node = parent[node]) {
    polyline.push_back(corners_[node].at);
  }
  polyline.push_back(start);
  std::reverse(polyline.begin(), polyline.end());
  return polyline;
}

RouteAnswer AreaRouter::FindRoute(const Vec2& start, const Vec2& goal) const {
  if (!start.allFinite() || !goal.allFinite()) {
    throw InputError("a route's start and goal must be finite numbers");
  }
  RouteAnswer answer;
  // Where an end enters the free space, and in which area.
  auto resolve = [&](const Vec2& point, const std::string& which, Vec2* inside, int* area) {
    *inside = point;
    *area = space_.AreaAt(point);
    if (*area >= 0) return true;
    const std::optional<Vec2> nearest = space_.NearestPoint(point, settings_.snap_distance_m);
    if (nearest) {
      *inside = *nearest;
      *area = space_.AreaAt(*nearest);
    }
    if (*area >= 0) return true;
    answer.no_route_reason = which + " " + PointText(point) + " is more than " +
                             FormatNumber(settings_.snap_distance_m) + " m from every area";
    return false;
  };
  Vec2 from, to;
  int from_area = -1, to_area = -1;
  if (!resolve(start, "the start", &from, &from_area) ||
      !resolve(goal, "the goal", &to, &to_area)) {
    return answer;
  }
  if (component_[from_area] != component_[to_area]) {
    answer.no_route_reason = "no passages join the start's area to the goal's";
    return answer;
  }
  std::optional<std::vector<Vec2>> polyline = ShortestPolyline(from, from_area, to, to_area);
  if (!polyline) {
    answer.no_route_reason = "no way through the free space joins the start and the goal";
    return answer;
  }
  Route route;
  if (from != start) route.polyline.push_back(start);
  route.polyline.insert(route.polyline.end(), polyline->begin(), polyline->end());
  if (to != goal) route.polyline.push_back(goal);
  for (size_t i = 0; i + 1 < route.polyline.size(); ++i) {
    route.length_m += (route.polyline[i + 1] - route.polyline[i]).norm();
  }
  Describe(&route);
  answer.route = std::move(route);
  return answer;
}

void AreaRouter::Describe(Route* route) const {
  std::vector<AreaVisit> visits;
  for (size_t i = 0; i + 1 < route->polyline.size(); ++i) {
    space_.AppendAreasAlong(route->polyline[i], route->polyline[i + 1], &visits);
  }
  for (size_t i = 0; i < visits.size(); ++i) {
    route->areas.push_back(visits[i].area);
    if (i == 0) continue;
    // The passage between the two areas nearest to where the route changes.
    int crossed = -1;
    double nearest = kInfinity;
    for (const int p : area_passages_[visits[i].area]) {
      const PassageLine& passage = passages_[p];
      if (passage.area_a != visits[i - 1].area && passage.area_b != visits[i - 1].area) continue;
      const double distance = DistanceToPolyline(visits[i].entry, passage.border);
      if (distance < nearest) {
        nearest = distance;
        crossed = p;
      }
    }
    if (crossed >= 0) route->passages.push_back(crossed);
  }
}

}  // namespace areagraph

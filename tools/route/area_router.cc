#include "tools/route/area_router.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numeric>
#include <queue>
#include <tuple>

#include "common/error.h"
#include "common/text.h"
#include "tools/route/vertex_passage.h"

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

// Whether segments ab and cd share a point, within kRouteTolerance (touching
// counts, as in FreeSpace).
bool SegmentsMeet(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d) {
  const double ab = std::max((b - a).norm(), kRouteTolerance);
  const double cd = std::max((d - c).norm(), kRouteTolerance);
  // Signed distances of each segment's ends from the other's line.
  const double abc = Cross(b - a, c - a) / ab, abd = Cross(b - a, d - a) / ab;
  const double cda = Cross(d - c, a - c) / cd, cdb = Cross(d - c, b - c) / cd;
  auto apart = [](double p, double q) {
    return (p > kRouteTolerance && q > kRouteTolerance) ||
           (p < -kRouteTolerance && q < -kRouteTolerance);
  };
  if (apart(abc, abd) || apart(cda, cdb)) return false;
  if (std::abs(abc) > kRouteTolerance || std::abs(abd) > kRouteTolerance) return true;
  // On one line: the two spans must overlap.
  const Vec2 axis = (b - a) / ab;
  const double tc = (c - a).dot(axis), td = (d - a).dot(axis);
  return std::max(tc, td) >= -kRouteTolerance && std::min(tc, td) <= ab + kRouteTolerance;
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
  std::vector<std::vector<FreeStretch>> stretches(vertices.size());
  std::map<std::pair<int, size_t>, int> corner_of_stretch;
  auto add = [&](int v, size_t s, bool reflex) {
    const FreeStretch& stretch = stretches[v][s];
    if (!corner_of_stretch.emplace(std::pair(v, s), corner_count()).second) return;
    corners_.push_back({vertices[v].at, reflex, stretch.walled, stretch.from_wall, stretch.to_wall,
                        stretch.areas, v});
  };
  for (size_t v = 0; v < vertices.size(); ++v) {
    stretches[v] = FreeStretches(vertices, vertices[v]);
    for (size_t s = 0; s < stretches[v].size(); ++s) {
      if (stretches[v][s].walled && stretches[v][s].angle > kHalfTurn + 1e-9) {
        add(static_cast<int>(v), s, /*reflex=*/true);
      }
    }
  }
  // The ends of every passage, so that each area's passages are linked
  // through the area even where no corner sticks out: in the stretch that the
  // passage's border runs into.
  for (const PassageLine& passage : passages_) {
    if (passage.border.empty()) continue;
    const size_t n = passage.border.size();
    for (const auto& [end, inward] : {std::pair(passage.border[0], passage.border[1]),
                                      std::pair(passage.border[n - 1], passage.border[n - 2])}) {
      const int v = space_.VertexAt(end);
      const int toward = space_.VertexAt(inward);
      bool found = false;
      for (size_t s = 0; v >= 0 && s < stretches[v].size(); ++s) {
        const std::vector<int>& rays = stretches[v][s].rays;
        if (std::find(rays.begin(), rays.end(), toward) == rays.end()) continue;
        add(v, s, stretches[v][s].walled && stretches[v][s].angle > kHalfTurn + 1e-9);
        found = true;
      }
      // A border off the outlines (a graph that breaks its own rules): a
      // corner that takes every direction.
      if (!found) {
        corners_.push_back(
            {end,
             false,
             false,
             Vec2::Zero(),
             Vec2::Zero(),
             {std::min(passage.area_a, passage.area_b), std::max(passage.area_a, passage.area_b)},
             v});
      }
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

bool AreaRouter::Admits(const Corner& corner, const Vec2& direction) {
  const double a = Cross(direction, corner.wall_a);
  const double b = Cross(direction, corner.wall_b);
  // (The walls are unit vectors; a sine under 1e-12 counts as parallel.)
  const double parallel = 1e-24 * direction.squaredNorm();
  if (corner.reflex) {
    // The walls' side of the corner (less than half a turn) must lie on one
    // side of the line, else the route could cut the corner short; then the
    // line lies in the corner's stretch.
    return !(a * b < 0 && a * a > parallel && b * b > parallel);
  }
  if (!corner.walled) return true;
  // Within the stretch (at most half a turn), from wall_a counter-clockwise
  // to wall_b, borders included: a route bends only inside one stretch.
  return (a <= 0 || a * a <= parallel) && (b >= 0 || b * b <= parallel);
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
          if (!Admits(from, direction) || !Admits(corners_[v], -direction)) continue;
          if (!ShareAnArea(from, corners_[v]) && !LeavesThroughAPassage(from, corners_[v].at)) {
            continue;
          }
          const bool inward = from.vertex >= 0 && space_.LeavesInto(from.vertex, direction);
          if (!space_.SegmentIsFree(from.at, corners_[v].at, inward)) continue;
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

bool AreaRouter::ShareAnArea(const Corner& a, const Corner& b) {
  for (const int area : a.areas) {
    if (std::find(b.areas.begin(), b.areas.end(), area) != b.areas.end()) return true;
  }
  return false;
}

bool AreaRouter::LeavesThroughAPassage(const Corner& from, const Vec2& to) const {
  for (const int area : from.areas) {
    if (LeavesThroughAPassage(from.at, area, to)) return true;
  }
  return false;
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

std::vector<std::pair<int, double>> AreaRouter::VisibleCorners(const Vec2& point, int area,
                                                               bool inside) const {
  std::vector<std::pair<int, double>> visible;
  for (const int c : EndCandidates(area)) {
    const Corner& corner = corners_[c];
    const Vec2 direction = corner.at - point;
    if (!Admits(corner, -direction)) continue;
    // Everything of the area's outline but its passages is wall: a line to
    // a corner of another area must cross one of them (a cheap test first).
    const bool own =
        std::find(corner.areas.begin(), corner.areas.end(), area) != corner.areas.end();
    if (!own && !LeavesThroughAPassage(point, area, corner.at)) continue;
    if (space_.SegmentIsFree(point, corner.at, inside)) {
      visible.emplace_back(c, direction.norm());
    }
  }
  return visible;
}

std::optional<std::vector<Vec2>> AreaRouter::ShortestPolyline(const End& start,
                                                              const End& goal) const {
  if (space_.SegmentIsFree(start.at, goal.at, start.inside)) {
    return std::vector<Vec2>{start.at, goal.at};
  }
  const int goal_node = corner_count();
  std::vector<double> to_goal(corners_.size(), kInfinity);
  for (const auto& [c, length] : VisibleCorners(goal.at, goal.area, goal.inside)) {
    to_goal[c] = length;
  }
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
    const double estimate = node == goal_node ? 0 : (goal.at - corners_[node].at).norm();
    open.emplace(length + estimate, node);
  };
  for (const auto& [c, length] : VisibleCorners(start.at, start.area, start.inside)) {
    reach(c, length, -1);
  }
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
  std::vector<Vec2> polyline{goal.at};
  for (int node = parent[goal_node]; node >= 0; node = parent[node]) {
    polyline.push_back(corners_[node].at);
  }
  polyline.push_back(start.at);
  std::reverse(polyline.begin(), polyline.end());
  return polyline;
}

RouteAnswer AreaRouter::FindRoute(const Vec2& start, const Vec2& goal) const {
  if (!start.allFinite() || !goal.allFinite()) {
    throw InputError("a route's start and goal must be finite numbers");
  }
  RouteAnswer answer;
  // Where an end enters the free space, and in which area.
  auto resolve = [&](const Vec2& point, const std::string& which, End* end) {
    end->at = point;
    end->area = space_.AreaAt(point);
    if (end->area >= 0) {
      end->inside = space_.StrictlyInside(point);
      return true;
    }
    const std::optional<Vec2> nearest = space_.NearestPoint(point, settings_.snap_distance_m);
    if (nearest) {
      end->at = *nearest;
      end->area = space_.AreaAt(*nearest);
    }
    if (end->area >= 0) return true;
    answer.no_route_reason = which + " " + PointText(point) + " is more than " +
                             FormatNumber(settings_.snap_distance_m) + " m from every area";
    return false;
  };
  End from, to;
  if (!resolve(start, "the start", &from) || !resolve(goal, "the goal", &to)) return answer;
  if (component_[from.area] != component_[to.area]) {
    answer.no_route_reason = "no passages join the start's area to the goal's";
    return answer;
  }
  std::optional<std::vector<Vec2>> polyline = ShortestPolyline(from, to);
  if (!polyline) {
    answer.no_route_reason = "no way through the free space joins the start and the goal";
    return answer;
  }
  Route route;
  if (from.at != start) route.polyline.push_back(start);
  route.polyline.insert(route.polyline.end(), polyline->begin(), polyline->end());
  if (to.at != goal) route.polyline.push_back(goal);
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

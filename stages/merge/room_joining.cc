#include "stages/merge/room_joining.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <vector>

#include "stages/geometry/disjoint_sets.h"
#include "stages/geometry/door_reach.h"
#include "stages/geometry/edge_polygon.h"

namespace areagraph {
namespace {

// An area's side of a graph vertex.
struct Side {
  // The narrowest opening (px) of the area's edge ends at the vertex: the
  // distance between the sites left and right of the edge there.
  double opening_px = 0;
  // The widest free width (px) along the area's edges within the reach.
  double widest_px = 0;
};

// The widest free width (px) along `edge` within `reach_px` of one end.
// Along a path segment the clearance is the distance to the segment's site,
// which is convex: the widest point of a stretch is one of its ends.
double WidestNearEnd(const proto::GraphEdge& edge, bool at_target, double reach_px) {
  const int segments = edge.left_sites_size();
  if (segments == 0 || edge.path_size() != segments + 1) return 0;
  double widest = 0, walked = 0;
  for (int step = 0; step < segments && walked < reach_px; ++step) {
    const int s = at_target ? segments - 1 - step : step;
    Eigen::Vector2d from = FromProtoPoint(edge.path(at_target ? s + 1 : s));
    Eigen::Vector2d to = FromProtoPoint(edge.path(at_target ? s : s + 1));
    const double length = (to - from).norm();
    if (walked + length > reach_px && length > 0) {
      to = from + (to - from) * ((reach_px - walked) / length);
    }
    const Eigen::Vector2d site = FromProtoPoint(edge.left_sites(s));
    widest = std::max({widest, (from - site).norm(), (to - site).norm()});
    walked += length;
  }
  return 2 * widest;
}

// The widest free width (px) within `reach_px` of `vertex` along the edges
// of `area`, walking on through the vertices they reach.
double WidestWithin(const proto::CutGraph& graph, const AreaPlan& plan,
                    const std::vector<std::vector<int>>& edges_at, int area, int vertex,
                    double reach_px) {
  double widest = 0;
  std::vector<std::pair<int, double>> todo{{vertex, reach_px}};
  std::vector<int> seen;
  while (!todo.empty()) {
    const auto [at, left] = todo.back();
    todo.pop_back();
    for (int e : edges_at[at]) {
      if (plan.area_of_edge[e] != area || std::count(seen.begin(), seen.end(), e)) continue;
      seen.push_back(e);
      const proto::GraphEdge& edge = graph.edges(e);
      const bool from_target = edge.target() == at;
      widest = std::max(widest, WidestNearEnd(edge, from_target, left));
      if (edge.length_px() < left) {
        todo.emplace_back(from_target ? edge.source() : edge.target(), left - edge.length_px());
      }
    }
  }
  return widest;
}

}  // namespace

void JoinRoomsWithoutDoors(const proto::CutGraph& graph, const PlanModel& model,
                           const std::vector<bool>& closed, AreaPlan* plan) {
  const double reach_px = kDoorReachM / model.resolution_m;
  std::vector<std::vector<int>> edges_at(graph.vertices_size());
  for (int e = 0; e < graph.edges_size(); ++e) {
    edges_at[graph.edges(e).source()].push_back(e);
    if (graph.edges(e).target() != graph.edges(e).source()) {
      edges_at[graph.edges(e).target()].push_back(e);
    }
  }
  std::vector<std::map<int, Side>> sides(graph.vertices_size());
  for (int e = 0; e < graph.edges_size(); ++e) {
    const proto::GraphEdge& edge = graph.edges(e);
    const int area = plan->area_of_edge[e];
    if (plan->areas[area].kind != proto::AREA_ROOM || edge.left_sites_size() == 0) continue;
    for (const bool at_target : {false, true}) {
      const int i = at_target ? edge.left_sites_size() - 1 : 0;
      const Side side{
          (FromProtoPoint(edge.left_sites(i)) - FromProtoPoint(edge.right_sites(i))).norm()};
      const int vertex = at_target ? edge.target() : edge.source();
      auto [it, added] = sides[vertex].emplace(area, side);
      if (added) {
        it->second.widest_px = WidestWithin(graph, *plan, edges_at, area, vertex, reach_px);
      } else {
        it->second.opening_px = std::min(it->second.opening_px, side.opening_px);
      }
    }
  }
  const int area_count = static_cast<int>(plan->areas.size());
  DisjointSets rooms(area_count);
  for (int vertex = 0; vertex < graph.vertices_size(); ++vertex) {
    const std::map<int, Side>& at = sides[vertex];
    for (auto a = at.begin(); a != at.end(); ++a) {
      for (auto b = std::next(a); b != at.end(); ++b) {
        const double opening = std::min(a->second.opening_px, b->second.opening_px);
        const double narrower_side = std::min(a->second.widest_px, b->second.widest_px);
        if (closed[vertex] && !(model.Corridor(a->first) && model.Corridor(b->first))) {
          continue;
        }
        if (opening > (1 - kSameWidthShare) * narrower_side) rooms.Union(a->first, b->first);
      }
    }
  }
  // Every room folds into the first room of its group.
  std::vector<int> root(area_count);
  for (int k = 0; k < area_count; ++k) root[k] = rooms.Find(k);
  plan->MergeGroups(root);
}

}  // namespace areagraph

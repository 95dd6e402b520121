#include "stages/merge/bay_folding.h"

#include <algorithm>
#include <map>
#include <vector>

#include "stages/geometry/door_reach.h"
#include "stages/geometry/edge_polygon.h"

namespace areagraph {
namespace {

// The narrowest free width (px) along `edge` within `reach_px` of one end.
double NarrowestNearEnd(const proto::GraphEdge& edge, bool at_target, double reach_px) {
  const int n = edge.clearance_px_size();
  if (n == 0 || edge.path_size() != n) return 0;
  double narrowest = edge.clearance_px(at_target ? n - 1 : 0);
  double walked = 0;
  for (int step = 1; step < n && walked <= reach_px; ++step) {
    const int i = at_target ? n - 1 - step : step;
    const int previous = at_target ? i + 1 : i - 1;
    walked += (FromProtoPoint(edge.path(i)) - FromProtoPoint(edge.path(previous))).norm();
    narrowest = std::min(narrowest, edge.clearance_px(i));
  }
  return 2 * narrowest;
}

}  // namespace

void FoldOpenBays(const proto::CutGraph& graph, const PlanModel& model, AreaPlan* plan) {
  const int area_count = static_cast<int>(plan->areas.size());
  std::vector<double> typical(area_count);
  std::vector<double> length(area_count, 0);
  for (int k = 0; k < area_count; ++k) {
    typical[k] = model.shapes[k].typical_px;
    for (int e : plan->areas[k].edges) length[k] += graph.edges(e).length_px();
  }
  const double reach_px = kDoorReachM / model.resolution_m;
  // Per vertex: area -> the narrowest width near the vertex along its edges.
  std::vector<std::map<int, double>> mouth_at(graph.vertices_size());
  for (int e = 0; e < graph.edges_size(); ++e) {
    const proto::GraphEdge& edge = graph.edges(e);
    const int area = plan->area_of_edge[e];
    for (const bool at_target : {false, true}) {
      const double width = NarrowestNearEnd(edge, at_target, reach_px);
      auto [it, added] = mouth_at[at_target ? edge.target() : edge.source()].emplace(area, width);
      if (!added) it->second = std::min(it->second, width);
    }
  }
  // The vertices each area touches, in vertex order: scanning every vertex for
  // every area took seconds on cluttered maps with thousands of each.
  std::vector<std::vector<int>> vertices_of(area_count);
  for (int v = 0; v < graph.vertices_size(); ++v) {
    for (const auto& [area, width] : mouth_at[v]) vertices_of[area].push_back(v);
  }
  std::vector<int> into(area_count, -1);
  for (int k = 0; k < area_count; ++k) {
    if (plan->areas[k].kind == proto::AREA_ROOM || length[k] > kMaxBayLengthWidths * typical[k]) {
      continue;
    }
    double widest = 0;
    for (const int v : vertices_of[k]) {
      const std::map<int, double>& at = mouth_at[v];
      const auto own = at.find(k);
      for (const auto& [other, width] : at) {
        const double mouth = std::min(own->second, width);
        if (plan->areas[other].kind != proto::AREA_ROOM ||
            mouth < (1 - kSameWidthShare) * typical[k] || mouth <= widest) {
          continue;
        }
        widest = mouth;
        into[k] = other;
      }
    }
  }
  // Rooms are never folded, so a target is never removed; indices above a
  // removed area shift down.
  for (int k = area_count - 1; k >= 0; --k) {
    if (into[k] < 0) continue;
    plan->MergeInto(k, into[k]);
    for (int j = 0; j < k; ++j) {
      if (into[j] > k) --into[j];
    }
  }
}

}  // namespace areagraph

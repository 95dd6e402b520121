#include "stages/merge/corridor_joining.h"

#include <algorithm>
#include <map>
#include <set>
#include <vector>

#include "stages/geometry/corridor_shape.h"
#include "stages/geometry/disjoint_sets.h"

namespace areagraph {
namespace {

bool IsUniform(const proto::GraphEdge& edge) {
  if (edge.clearance_px_size() == 0) return false;
  std::vector<double> clearance(edge.clearance_px().begin(), edge.clearance_px().end());
  std::nth_element(clearance.begin(), clearance.begin() + clearance.size() / 2, clearance.end());
  const double median = clearance[clearance.size() / 2];
  const double smallest = *std::min_element(edge.clearance_px().begin(), edge.clearance_px().end());
  return !NarrowsCorridor(smallest, median);
}

// The bit of corridor in front of a door that AssignAreas gave to a corridor
// piece: it leads to a passage point and lies within the free disks of its
// ends. Its narrowing is the door's, not one along the corridor.
bool IsDoorwayStub(const proto::CutGraph& graph, const proto::GraphEdge& edge) {
  const proto::GraphVertex& source = graph.vertices(edge.source());
  const proto::GraphVertex& target = graph.vertices(edge.target());
  const bool to_door =
      source.kind() == proto::VERTEX_PASSAGE || target.kind() == proto::VERTEX_PASSAGE;
  return to_door && edge.length_px() <= source.clearance_px() + target.clearance_px();
}

}  // namespace

void JoinCorridorPieces(const proto::CutGraph& graph, AreaPlan* plan) {
  const int area_count = static_cast<int>(plan->areas.size());
  std::vector<bool> joinable(area_count);
  for (int k = 0; k < area_count; ++k) {
    joinable[k] = plan->areas[k].kind != proto::AREA_ROOM;
    for (int e : plan->areas[k].edges) {
      const proto::GraphEdge& edge = graph.edges(e);
      joinable[k] = joinable[k] && (IsUniform(edge) || IsDoorwayStub(graph, edge));
    }
  }
  std::vector<std::set<int>> joinable_at(graph.vertices_size());
  for (int e = 0; e < graph.edges_size(); ++e) {
    const int area = plan->area_of_edge[e];
    if (!joinable[area]) continue;
    for (int vertex : {graph.edges(e).source(), graph.edges(e).target()}) {
      if (graph.vertices(vertex).kind() != proto::VERTEX_DEAD_END) joinable_at[vertex].insert(area);
    }
  }
  DisjointSets groups(area_count);
  for (const std::set<int>& areas : joinable_at) {
    // Two pieces: a corridor going on past a door. Three or more: corridors
    // that fork, a place of its own in the topology (mazes are all forks).
    if (areas.size() == 2) groups.Union(*areas.begin(), *areas.rbegin());
  }
  AreaPlan joined;
  joined.area_of_edge.assign(plan->area_of_edge.size(), -1);
  std::map<int, int> area_of_group;
  for (int k = 0; k < area_count; ++k) {
    const AreaPlan::Area& piece = plan->areas[k];
    const auto [it, added] =
        area_of_group.emplace(groups.Find(k), static_cast<int>(joined.areas.size()));
    if (added) {
      joined.areas.push_back(piece);
      continue;
    }
    AreaPlan::Area& into = joined.areas[it->second];
    into.edges.insert(into.edges.end(), piece.edges.begin(), piece.edges.end());
    if (piece.kind == proto::AREA_CORRIDOR) into.kind = proto::AREA_CORRIDOR;
  }
  for (size_t k = 0; k < joined.areas.size(); ++k) {
    std::sort(joined.areas[k].edges.begin(), joined.areas[k].edges.end());
    for (int e : joined.areas[k].edges) joined.area_of_edge[e] = static_cast<int>(k);
  }
  *plan = std::move(joined);
}

}  // namespace areagraph

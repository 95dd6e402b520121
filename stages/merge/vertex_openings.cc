#include "stages/merge/vertex_openings.h"

namespace areagraph {

std::vector<std::map<int, VertexOpening>> OpeningsAtVertices(const proto::CutGraph& graph,
                                                             const AreaPlan& plan) {
  std::vector<std::map<int, VertexOpening>> openings(graph.vertices_size());
  for (int e = 0; e < graph.edges_size(); ++e) {
    const proto::GraphEdge& edge = graph.edges(e);
    const int segments = edge.left_sites_size();
    if (segments == 0 || edge.right_sites_size() != segments) continue;
    for (const bool at_target : {false, true}) {
      const int i = at_target ? segments - 1 : 0;
      VertexOpening opening;
      opening.left = FromProtoPoint(edge.left_sites(i));
      opening.right = FromProtoPoint(edge.right_sites(i));
      opening.width_px = (opening.left - opening.right).norm();
      const int vertex = at_target ? edge.target() : edge.source();
      auto [it, added] = openings[vertex].emplace(plan.area_of_edge[e], opening);
      if (!added && opening.width_px < it->second.width_px) it->second = opening;
    }
  }
  return openings;
}

std::vector<bool> ClosedVertices(const proto::CutGraph& graph) {
  std::vector<bool> closed(graph.vertices_size(), false);
  for (const proto::PassagePoint& passage : graph.passage_points()) {
    if (passage.closed_by_cut() && passage.vertex() >= 0 &&
        passage.vertex() < graph.vertices_size()) {
      closed[passage.vertex()] = true;
    }
  }
  return closed;
}

}  // namespace areagraph

#include "stages/merge/passage_finder.h"

#include <algorithm>
#include <map>

#include "stages/geometry/edge_polygon.h"

namespace areagraph {
namespace {

struct Opening {
  Eigen::Vector2d left, right;
  double Width() const { return (left - right).norm(); }
};

Opening OpeningAt(const proto::GraphEdge& edge, bool at_target) {
  const int i = at_target ? edge.left_sites_size() - 1 : 0;
  return {FromProtoPoint(edge.left_sites(i)), FromProtoPoint(edge.right_sites(i))};
}

}  // namespace

std::vector<PassagePlan> FindPassages(const proto::CutGraph& graph,
                                      const std::vector<int>& area_of_edge) {
  // The narrowest opening of each area at each vertex.
  std::vector<std::map<int, Opening>> openings(graph.vertices_size());
  for (int e = 0; e < graph.edges_size(); ++e) {
    const proto::GraphEdge& edge = graph.edges(e);
    const int area = area_of_edge[e];
    if (area < 0 || edge.left_sites_size() == 0) continue;
    for (const bool at_target : {false, true}) {
      const Opening opening = OpeningAt(edge, at_target);
      auto& at_vertex = openings[at_target ? edge.target() : edge.source()];
      const auto [it, added] = at_vertex.emplace(area, opening);
      if (!added && opening.Width() < it->second.Width()) it->second = opening;
    }
  }

  std::map<std::pair<int, int>, std::vector<PassagePlan>> by_pair;
  for (int v = 0; v < graph.vertices_size(); ++v) {
    const Eigen::Vector2d point = FromProtoPoint(graph.vertices(v).position());
    for (auto a = openings[v].begin(); a != openings[v].end(); ++a) {
      for (auto b = std::next(a); b != openings[v].end(); ++b) {
        const Opening& narrow = a->second.Width() <= b->second.Width() ? a->second : b->second;
        PassagePlan passage{a->first, b->first, point, narrow.left, narrow.right, narrow.Width()};
        std::vector<PassagePlan>& same_pair = by_pair[{a->first, b->first}];
        // One opening seen from two nearby vertices is one passage.
        auto twin = std::find_if(same_pair.begin(), same_pair.end(), [&](const PassagePlan& p) {
          return (p.point - point).norm() <= 0.5 * std::max(p.width_px, passage.width_px);
        });
        if (twin == same_pair.end()) {
          same_pair.push_back(passage);
        } else if (passage.width_px < twin->width_px) {
          *twin = passage;
        }
      }
    }
  }
  std::vector<PassagePlan> passages;
  for (const auto& [pair, list] : by_pair)
    passages.insert(passages.end(), list.begin(), list.end());
  return passages;
}

}  // namespace areagraph

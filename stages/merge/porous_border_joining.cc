#include "stages/merge/porous_border_joining.h"

#include <algorithm>
#include <limits>
#include <map>
#include <utility>
#include <vector>

#include "stages/geometry/disjoint_sets.h"

namespace areagraph {

void JoinAtPorousBorders(const proto::CutGraph& graph, const PlanModel& model,
                         const std::vector<bool>& closed, double narrow_gap_px, AreaPlan* plan) {
  const int area_count = static_cast<int>(plan->areas.size());
  const std::vector<std::map<int, VertexOpening>>& openings = model.openings;
  struct Border {
    int vertices = 0;
    double narrowest_px = std::numeric_limits<double>::infinity();
  };
  std::map<std::pair<int, int>, Border> borders;
  for (int vertex = 0; vertex < graph.vertices_size(); ++vertex) {
    if (closed[vertex]) continue;
    const std::map<int, VertexOpening>& at = openings[vertex];
    for (auto a = at.begin(); a != at.end(); ++a) {
      for (auto b = std::next(a); b != at.end(); ++b) {
        Border& border = borders[{a->first, b->first}];
        ++border.vertices;
        border.narrowest_px =
            std::min({border.narrowest_px, a->second.width_px, b->second.width_px});
      }
    }
  }
  DisjointSets groups(area_count);
  bool joined = false;
  for (const auto& [pair, border] : borders) {
    if (border.vertices < kPorousMinOpenings || border.narrowest_px >= narrow_gap_px) continue;
    joined |= groups.Union(pair.first, pair.second);
  }
  if (!joined) return;
  std::map<int, int> lead;
  for (int k = 0; k < area_count; ++k) {
    auto [it, added] = lead.emplace(groups.Find(k), k);
    if (!added && model.shapes[k].area_px > model.shapes[it->second].area_px) it->second = k;
  }
  MergeGroupsLedBy(groups, lead, plan);
}

}  // namespace areagraph

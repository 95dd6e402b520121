#include "stages/merge/corridor_piece_folding.h"

#include <map>
#include <vector>

#include "stages/geometry/disjoint_sets.h"

namespace areagraph {

void FoldCorridorPieces(const proto::CutGraph& graph, const PlanModel& model,
                        const std::vector<bool>& closed, double max_m2, AreaPlan* plan) {
  const int area_count = static_cast<int>(plan->areas.size());
  const double max_px = max_m2 / (model.resolution_m * model.resolution_m);
  const std::vector<AreaShape>& shapes = model.shapes;
  const std::vector<std::map<int, VertexOpening>>& openings = model.openings;
  // Each small room's widest qualifying opening, and the area behind it.
  std::vector<int> into(area_count, -1);
  std::vector<double> widest(area_count, 0);
  std::vector<int> wide_openings(area_count, 0);
  for (int vertex = 0; vertex < graph.vertices_size(); ++vertex) {
    if (closed[vertex]) continue;
    const std::map<int, VertexOpening>& at = openings[vertex];
    for (const auto& [k, own] : at) {
      if (plan->areas[k].kind != proto::AREA_ROOM || shapes[k].area_px >= max_px ||
          shapes[k].typical_px <= 0) {
        continue;
      }
      for (const auto& [other, theirs] : at) {
        if (other == k) continue;
        if (plan->areas[other].kind == proto::AREA_ROOM && !shapes[other].corridor) continue;
        const double opening = std::min(own.width_px, theirs.width_px);
        if (opening < (1 - kSameWidthShare) * shapes[k].typical_px) continue;
        ++wide_openings[k];
        if (opening <= widest[k]) continue;
        widest[k] = opening;
        into[k] = other;
      }
    }
  }
  DisjointSets groups(area_count);
  std::vector<bool> folded(area_count, false);
  for (int k = 0; k < area_count; ++k) {
    if (into[k] < 0 || wide_openings[k] < kMinWideOpenings) continue;
    groups.Union(k, into[k]);
    folded[k] = true;
  }
  // A group takes the kind (and room) of its biggest area that did not fold
  // (of its biggest area when all folded into each other).
  std::map<int, int> lead;
  for (int pass = 0; pass < 2; ++pass) {
    for (int k = 0; k < area_count; ++k) {
      if (pass == 0 && folded[k]) continue;
      auto [it, added] = lead.emplace(groups.Find(k), k);
      if (!added && pass == 0 && shapes[k].area_px > shapes[it->second].area_px) it->second = k;
    }
  }
  MergeGroupsLedBy(groups, lead, plan);
}

}  // namespace areagraph

#include "stages/merge/corridor_stem_joining.h"

#include <algorithm>
#include <limits>
#include <map>
#include <vector>

#include "stages/geometry/corridor_shape.h"
#include "stages/geometry/disjoint_sets.h"
#include "stages/merge/area_shapes.h"
#include "stages/merge/vertex_openings.h"

namespace areagraph {

void JoinCorridorStems(const proto::CutGraph& graph, const PlanModel& model,
                       const std::vector<bool>& closed, AreaPlan* plan) {
  const double resolution_m = model.resolution_m;
  const int area_count = static_cast<int>(plan->areas.size());
  const std::vector<AreaShape>& shapes = model.shapes;
  const std::vector<std::map<int, VertexOpening>>& openings = model.openings;
  // Per area: the one area it meets at open vertices (-1: none, -2: more
  // than one) and its narrowest opening there.
  std::vector<int> neighbour(area_count, -1);
  std::vector<double> mouth(area_count, std::numeric_limits<double>::infinity());
  for (int vertex = 0; vertex < graph.vertices_size(); ++vertex) {
    if (closed[vertex]) continue;
    const std::map<int, VertexOpening>& at = openings[vertex];
    if (at.size() < 2) continue;
    for (const auto& [area, opening] : at) {
      mouth[area] = std::min(mouth[area], opening.width_px);
      for (const auto& [other, unused] : at) {
        if (other == area) continue;
        if (neighbour[area] == -1) neighbour[area] = other;
        if (neighbour[area] != other) neighbour[area] = -2;
      }
    }
  }
  DisjointSets groups(area_count);
  std::vector<int> joined;  // the corridors that take a stem
  for (int stem = 0; stem < area_count; ++stem) {
    const AreaPlan::Area& area = plan->areas[stem];
    const int corridor = neighbour[stem];
    if (area.kind != proto::AREA_DEAD_END || area.room_id >= 0 || corridor < 0) continue;
    const double w = shapes[stem].typical_px;
    if (NarrowsCorridor(mouth[stem], w)) continue;
    if (!shapes[stem].corridor) continue;
    const AreaPlan::Area& into = plan->areas[corridor];
    const double corridor_width = shapes[corridor].typical_px;
    const bool corridor_shaped =
        into.room_id < 0 ? into.kind == proto::AREA_CORRIDOR : shapes[corridor].corridor;
    if (!corridor_shaped || w * kCorridorWidthRatio > corridor_width) continue;
    if (corridor_width * resolution_m > kMaxCorridorWidthM) continue;
    groups.Union(stem, corridor);
    joined.push_back(corridor);
  }
  if (joined.empty()) return;
  // A stem joins one corridor and no corridor is a stem: each group is one
  // corridor and its stems, led by the corridor.
  std::map<int, int> leads;
  for (const int corridor : joined) leads[groups.Find(corridor)] = corridor;
  for (int k = 0; k < area_count; ++k) leads.emplace(groups.Find(k), k);
  MergeGroupsLedBy(groups, leads, plan);
}

}  // namespace areagraph

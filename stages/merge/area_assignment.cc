#include "stages/merge/area_assignment.h"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <map>
#include <unordered_map>

#include "stages/geometry/disjoint_sets.h"
#include "stages/geometry/edge_polygon.h"
#include "stages/geometry/ring_area.h"
#include "stages/geometry/ring_simplicity.h"

namespace areagraph {
namespace {

bool IsStub(const proto::CutGraph& graph, const proto::GraphEdge& edge, int* junction) {
  if (edge.room_id() >= 0 || edge.source() == edge.target()) return false;
  const proto::GraphVertex& source = graph.vertices(edge.source());
  const proto::GraphVertex& target = graph.vertices(edge.target());
  const proto::GraphVertex* passage = nullptr;
  const proto::GraphVertex* fork = nullptr;
  if (source.kind() == proto::VERTEX_PASSAGE && target.kind() == proto::VERTEX_JUNCTION) {
    passage = &source, fork = &target;
  } else if (target.kind() == proto::VERTEX_PASSAGE && source.kind() == proto::VERTEX_JUNCTION) {
    passage = &target, fork = &source;
  } else {
    return false;
  }
  *junction = fork->id();
  return edge.length_px() <= passage->clearance_px() + fork->clearance_px();
}

}  // namespace

void AreaPlan::MergeInto(int from, int into) {
  for (int e : areas[from].edges) area_of_edge[e] = into;
  Area& target = areas[into];
  target.edges.insert(target.edges.end(), areas[from].edges.begin(), areas[from].edges.end());
  std::sort(target.edges.begin(), target.edges.end());
  areas.erase(areas.begin() + from);
  for (int& area : area_of_edge) {
    if (area > from) --area;
  }
}

void AreaPlan::MergeGroups(std::vector<int> group) {
  // What MergeInto, called for every area after the first of its group from
  // the last area down, leaves; in one pass over the areas and the edges
  // instead of one per merged area (quadratic in the areas).
  const int count = static_cast<int>(group.size());
  std::unordered_map<int, int> first_of_group;
  std::vector<int> first(count);
  for (int k = 0; k < count; ++k) first[k] = first_of_group.emplace(group[k], k).first->second;
  // removed_below[v]: how many merged areas have an index below v.
  std::vector<int> removed_below(count + 1, 0);
  for (int k = 0; k < count; ++k) removed_below[k + 1] = removed_below[k] + (first[k] != k);
  if (removed_below[count] == 0) return;
  // From the last area down, as MergeInto went: an edge of two merged areas
  // ends in the lower one's group.
  for (int k = count - 1; k >= 0; --k) {
    if (first[k] == k) continue;
    for (const int e : areas[k].edges) area_of_edge[e] = first[k];
  }
  for (int& area : area_of_edge) {
    if (area > 0) area -= removed_below[std::min(area, count)];
  }
  std::vector<bool> grew(count, false);
  for (int k = count - 1; k >= 0; --k) {
    if (first[k] == k) continue;
    std::vector<int>& target = areas[first[k]].edges;
    target.insert(target.end(), areas[k].edges.begin(), areas[k].edges.end());
    grew[first[k]] = true;
  }
  std::vector<Area> kept;
  kept.reserve(count - removed_below[count]);
  for (int k = 0; k < count; ++k) {
    if (first[k] != k) continue;
    kept.push_back(std::move(areas[k]));
    if (grew[k]) std::sort(kept.back().edges.begin(), kept.back().edges.end());
  }
  areas.erase(areas.begin(), areas.begin() + count);
  areas.insert(areas.begin(), std::make_move_iterator(kept.begin()),
               std::make_move_iterator(kept.end()));
}

void MergeGroupsLedBy(DisjointSets& groups, const std::map<int, int>& lead, AreaPlan* plan) {
  const int area_count = static_cast<int>(plan->areas.size());
  std::vector<int> root(area_count);
  for (int k = 0; k < area_count; ++k) {
    root[k] = groups.Find(k);
    const AreaPlan::Area& target = plan->areas[lead.at(root[k])];
    plan->areas[k].kind = target.kind;
    plan->areas[k].room_id = target.room_id;
  }
  plan->MergeGroups(root);
}

AreaPlan AssignAreas(const proto::CutGraph& graph) {
  const int edge_count = graph.edges_size();
  DisjointSets groups(edge_count);
  std::map<int, int> first_edge_of_room;
  std::vector<std::vector<int>> edges_at(graph.vertices_size());
  for (int e = 0; e < edge_count; ++e) {
    const proto::GraphEdge& edge = graph.edges(e);
    edges_at[edge.source()].push_back(e);
    if (edge.target() != edge.source()) edges_at[edge.target()].push_back(e);
    if (edge.room_id() < 0) continue;
    const auto [it, added] = first_edge_of_room.emplace(edge.room_id(), e);
    if (!added) groups.Union(it->second, e);
  }
  for (int e = 0; e < edge_count; ++e) {
    int junction = -1;
    if (!IsStub(graph, graph.edges(e), &junction)) continue;
    // The longest other room-less edge at the junction, else the longest one.
    int best = -1;
    for (int other : edges_at[junction]) {
      if (other == e) continue;
      const bool roomless = graph.edges(other).room_id() < 0;
      if (best < 0) {
        best = other;
        continue;
      }
      const bool best_roomless = graph.edges(best).room_id() < 0;
      if (roomless != best_roomless
              ? roomless
              : graph.edges(other).length_px() > graph.edges(best).length_px()) {
        best = other;
      }
    }
    if (best >= 0) groups.Union(e, best);
  }

  AreaPlan plan;
  plan.area_of_edge.assign(edge_count, -1);
  std::map<int, int> area_of_group;
  for (int e = 0; e < edge_count; ++e) {
    const auto [it, added] =
        area_of_group.emplace(groups.Find(e), static_cast<int>(plan.areas.size()));
    if (added) plan.areas.emplace_back();
    plan.area_of_edge[e] = it->second;
    plan.areas[it->second].edges.push_back(e);
  }
  for (AreaPlan::Area& area : plan.areas) {
    bool dead_end = false;
    for (int e : area.edges) {
      const proto::GraphEdge& edge = graph.edges(e);
      if (edge.room_id() >= 0) area.room_id = edge.room_id();
      dead_end = dead_end || graph.vertices(edge.source()).kind() == proto::VERTEX_DEAD_END ||
                 graph.vertices(edge.target()).kind() == proto::VERTEX_DEAD_END;
    }
    area.kind = area.room_id >= 0 ? proto::AREA_ROOM
                                  : (dead_end ? proto::AREA_DEAD_END : proto::AREA_CORRIDOR);
  }
  return plan;
}

std::vector<std::set<int>> AreasAtVertices(const proto::CutGraph& graph, const AreaPlan& plan) {
  std::vector<std::set<int>> areas_at(graph.vertices_size());
  for (int e = 0; e < graph.edges_size(); ++e) {
    areas_at[graph.edges(e).source()].insert(plan.area_of_edge[e]);
    areas_at[graph.edges(e).target()].insert(plan.area_of_edge[e]);
  }
  return areas_at;
}

double MedianWidthPx(const proto::CutGraph& graph, const AreaPlan::Area& area) {
  std::vector<double> clearance;
  for (int e : area.edges) {
    const auto& samples = graph.edges(e).clearance_px();
    clearance.insert(clearance.end(), samples.begin(), samples.end());
  }
  if (clearance.empty()) return 0;
  std::nth_element(clearance.begin(), clearance.begin() + clearance.size() / 2, clearance.end());
  return 2 * clearance[clearance.size() / 2];
}

std::vector<double> AreaSizesM2(const proto::CutGraph& graph, const AreaPlan& plan,
                                double resolution_m) {
  std::vector<double> size(plan.areas.size(), 0);
  const double cell_m2 = resolution_m * resolution_m;
  for (int e = 0; e < graph.edges_size(); ++e) {
    double& area = size[plan.area_of_edge[e]];
    // Half of TwiceSignedArea is SignedArea's value bit for bit (the same
    // products, summed in the same order), without a copy of the points.
    area += cell_m2 * std::abs(0.5 * TwiceSignedArea(graph.edges(e).polygon().outer()));
    for (const proto::Polygon& absorbed : graph.edges(e).absorbed()) {
      area += cell_m2 * std::abs(0.5 * TwiceSignedArea(absorbed.outer()));
    }
  }
  return size;
}

}  // namespace areagraph

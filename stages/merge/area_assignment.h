#pragma once

#include <map>
#include <set>
#include <vector>

#include "proto/artifacts.pb.h"
#include "stages/geometry/disjoint_sets.h"

namespace areagraph {

// Which CutGraph edges make up each area.
struct AreaPlan {
  struct Area {
    proto::AreaKind kind = proto::AREA_CORRIDOR;
    // The room of a room area, else -1.
    int room_id = -1;
    std::vector<int> edges;
  };
  std::vector<Area> areas;
  // Area index of every edge (by position in CutGraph.edges).
  std::vector<int> area_of_edge;

  // Moves all edges of area `from` to area `into` and removes `from`
  // (indices of later areas shift down by one).
  void MergeInto(int from, int into);
  // Merges every area into the first area of its group (areas j and k are
  // in one group when group[j] == group[k]), keeping that area's kind.
  void MergeGroups(std::vector<int> group);
};

// Merges the areas of each group of `groups` (over area indices) into one area, which takes the
// kind and room of the group's lead (`lead` maps each group's root to its lead area).
void MergeGroupsLedBy(DisjointSets& groups, const std::map<int, int>& lead, AreaPlan* plan);

// The areas of a CutGraph: all edges of one room form one room area; every
// room-less edge is an area of its own (a dead end when it ends at a dead
// end, else a corridor), except a stub: a room-less edge from a junction to a
// passage point that is no longer than the clearances at its two ends (it
// lies inside their free disks, like the bit of corridor in front of a door)
// joins the longest other room-less edge at its junction (or, when there is
// none, the longest edge there, so that it becomes part of that room).
AreaPlan AssignAreas(const proto::CutGraph& graph);

// The areas whose edges end at each graph vertex, by vertex.
std::vector<std::set<int>> AreasAtVertices(const proto::CutGraph& graph, const AreaPlan& plan);

// Median free width (px) of an area: twice the median clearance along its
// edges (0 without clearances).
double MedianWidthPx(const proto::CutGraph& graph, const AreaPlan::Area& area);

// The size (m2) of each area of `plan`: its edges' polygons and what they absorbed.
std::vector<double> AreaSizesM2(const proto::CutGraph& graph, const AreaPlan& plan,
                                double resolution_m);

}  // namespace areagraph

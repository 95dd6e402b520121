#pragma once

#include <map>
#include <vector>

#include "proto/artifacts.pb.h"
#include "stages/merge/area_assignment.h"
#include "stages/merge/area_shapes.h"
#include "stages/merge/vertex_openings.h"

namespace areagraph {

// What the merge passes read about a plan as it stands: every area's shape
// and every opening between areas at a graph vertex. Measured once for each
// state of the plan (RunMergePasses measures it again after a pass that
// changed the plan); no pass measures these itself.
struct PlanModel {
  double resolution_m = 0;
  // Per area of the plan.
  std::vector<AreaShape> shapes;
  // Per graph vertex: area -> its narrowest opening there.
  std::vector<std::map<int, VertexOpening>> openings;
  // Per area: at how many graph vertices it meets another area.
  std::vector<int> exits;

  // Whether area k is a corridor as the areas' kinds say: shaped like one
  // and a way through (it meets other areas at two places or more), not a
  // long room behind one door.
  bool Corridor(int k) const { return shapes[k].corridor && exits[k] >= 2; }
};

PlanModel MeasurePlan(const proto::CutGraph& graph, const AreaPlan& plan, double resolution_m);

}  // namespace areagraph

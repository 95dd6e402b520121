#include "stages/merge/plan_model.h"

namespace areagraph {

PlanModel MeasurePlan(const proto::CutGraph& graph, const AreaPlan& plan, double resolution_m) {
  PlanModel model{resolution_m, MeasureAreaShapes(graph, plan, resolution_m),
                  OpeningsAtVertices(graph, plan), std::vector<int>(plan.areas.size(), 0)};
  for (const std::map<int, VertexOpening>& at : model.openings) {
    if (at.size() < 2) continue;
    for (const auto& [area, unused] : at) ++model.exits[area];
  }
  return model;
}

}  // namespace areagraph

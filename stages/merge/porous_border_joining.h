#pragma once

#include <vector>

#include "proto/artifacts.pb.h"
#include "stages/merge/area_assignment.h"
#include "stages/merge/plan_model.h"

namespace areagraph {

// A border between two areas is porous when they meet at this many graph
// vertices or more: a wall between two rooms has a door or two.
inline constexpr int kPorousMinOpenings = 3;

// Joins two areas that meet at kPorousMinOpenings or more graph vertices, at
// least one of them an opening narrower than `narrow_gap_px` (the robot's
// width, CleanedMap.robot_width_m: one nobody walks through, so no door).
// Clutter standing in one room (shelves, desks, scanned chair legs) leaves
// such a border of many openings and the room disk stops at it; a wall with
// doors does not. `closed` vertices (where
// ag-cut closed a door or wall gap on purpose, ClosedVertices) do not count.
// A joined group takes the kind of its biggest area.
void JoinAtPorousBorders(const proto::CutGraph& graph, const PlanModel& model,
                         const std::vector<bool>& closed, double narrow_gap_px, AreaPlan* plan);

}  // namespace areagraph

#pragma once

#include <vector>

#include "proto/artifacts.pb.h"
#include "stages/merge/area_assignment.h"
#include "stages/merge/plan_model.h"

namespace areagraph {

// Joins a room-less dead end (AREA_DEAD_END) into the corridor it opens
// from: every vertex where it meets another area, other than `closed` ones
// (ClosedVertices), joins it to one and the same area, which is a corridor
// at most kMaxCorridorWidthM wide (room-less, or a room shaped like a
// corridor, AreaShape.corridor) more than kCorridorWidthRatio times as wide
// as the stem (one about as wide as the corridor is a room without a door or
// the corridor's own end, as wide as the rest). The stem does not narrow at
// its mouth (NarrowsCorridor against its own median free width: a closet or
// a room is wider than its door) and is shaped like a corridor.
// A dead-end branch narrower than W gets no room, and JoinSplitCorridors keeps it apart from a
// corridor more than kCorridorWidthRatio times as wide; a hall (wider than a corridor) keeps its
// narrow tails, which cut pass CUT_NARROW_TAILS made areas of their own, apart. The constants were
// chosen on the generated tuning and tuning-extra floors and the real maps (docs/quality.md,
// "Options beyond the paper").
void JoinCorridorStems(const proto::CutGraph& graph, const PlanModel& model,
                       const std::vector<bool>& closed, AreaPlan* plan);

}  // namespace areagraph

#pragma once

#include <vector>

#include "proto/artifacts.pb.h"
#include "stages/merge/area_assignment.h"
#include "stages/merge/plan_model.h"

namespace areagraph {

// The constants of JoinCorridorStems, chosen on the generated tuning and
// tuning-extra floors and the real maps (docs/quality.md, "Options beyond the paper").
struct CorridorStemParams {
  // The stem is at least this wide (metres): a walkable passage.
  double min_width_m = 0.7;
  // A branch: the stem is at most this share of the corridor's median free
  // width. One about as wide as the corridor (JoinSplitCorridors' width
  // ratio) is a room without a door or the corridor's own end, as wide as
  // the rest (an office at a corridor's end, as wide as the corridor).
  double max_width_share = 0.8;
};

// Joins a room-less dead end (AREA_DEAD_END) into the corridor it opens
// from: every vertex where it meets another area, other than `closed` ones
// (ClosedVertices), joins it to one and the same area, which is a corridor
// at most kMaxCorridorWidthM wide (room-less, or a room shaped like a
// corridor, AreaShape.corridor) clearly wider than the stem; the stem does
// not narrow at its mouth (kCorridorOpeningShare of its own median free
// width: a closet or a room is wider than its door), is shaped like a
// corridor and straight (kStraightAxisRatio), by the constants above. A dead-end branch narrower
// than W gets no room, and JoinSplitCorridors keeps it apart from a corridor more than 1.3 times as
// wide; a hall (wider than a corridor) keeps its narrow tails, which
// cut.cut_narrow_tails made areas of their own, apart.
void JoinCorridorStems(const proto::CutGraph& graph, const PlanModel& model,
                       const std::vector<bool>& closed, AreaPlan* plan,
                       const CorridorStemParams& params = {});

}  // namespace areagraph

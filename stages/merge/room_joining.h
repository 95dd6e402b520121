#pragma once

#include <vector>

#include "proto/artifacts.pb.h"
#include "stages/merge/area_assignment.h"
#include "stages/merge/plan_model.h"
#include "stages/merge/vertex_openings.h"

namespace areagraph {

// Joins room areas that meet at a graph vertex without a narrowing between
// them: the opening there is not narrower than 1 - kSameWidthShare of the space on
// the narrower side (the widest within kDoorReachM of it, stages/geometry/door_reach.h: past a
// door's depth and its stub, the space behind it has its own width, as ag-cut's door finding reads
// it). The room disk stopped there (at a piece of furniture or a bend), but nothing divides the
// room; a door is narrower than the rooms it joins. (A second cue, how deep the narrowing is,
// separated furniture gaps from doors on the generated floors but merged real rooms on the scanned
// maps, whose doorways are deep: dropped, see docs/quality.md.) Rooms that meet at a `closed`
// vertex (a cut ag-cut made on a door or wall gap it closed, ClosedVertices) stay apart: their
// jambs are walls. Not when both rooms are corridors (PlanModel::Corridor:
// shaped like one and open into two areas or more): the cut's thin wall end
// is then the corner where one corridor meets another.
void JoinRoomsWithoutDoors(const proto::CutGraph& graph, const PlanModel& model,
                           const std::vector<bool>& closed, AreaPlan* plan);

}  // namespace areagraph

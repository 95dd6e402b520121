#pragma once

#include "proto/artifacts.pb.h"
#include "stages/merge/area_assignment.h"
#include "stages/merge/plan_model.h"
#include "stages/merge/vertex_openings.h"

namespace areagraph {

// A bay is at most this many times as long (its graph edges) as it is wide;
// longer room-less areas are corridors, which stay apart even where they
// open into a room through a wide opening. Below kCorridorElongation (4
// squares): a bay is shorter than any corridor.
inline constexpr double kMaxBayLengthWidths = 3.0;

// Folds short room-less areas into a room they open into without narrowing
// (the narrowest free width near the vertex where they meet, on both sides
// and within kDoorReachM of it, stages/geometry/door_reach.h: the mouth and
// the stretch in front of it, not the area's far end, is at least
// 1 - kSameWidthShare of the area's typical free width): a bay of a room that the
// room disk (W) could not reach, e.g. the strip between a row of tables and
// the wall, is part of the room, while a corridor meets a room through a
// door narrower than itself or is long. Of several such rooms the one with
// the widest opening wins.
void FoldOpenBays(const proto::CutGraph& graph, const PlanModel& model, AreaPlan* plan);

}  // namespace areagraph

#pragma once

#include <vector>

#include "proto/artifacts.pb.h"
#include "stages/merge/area_assignment.h"
#include "stages/merge/plan_model.h"
#include "stages/merge/vertex_openings.h"

namespace areagraph {

// A piece of corridor opens widely to both sides (or more, at a junction);
// a room with one wide opening is a room with an open front.
inline constexpr int kMinWideOpenings = 2;

// Folds room areas smaller than `max_m2` (their edges' polygons) that have
// at least kMinWideOpenings openings (at graph vertices) into corridors at
// least 1 - kSameWidthShare (vertex_openings.h) of their own typical free width wide, into the
// corridor behind the widest one. A corridor here is a room-less area or a
// room area shaped like a corridor (AreaShape.corridor). The room disk (W) fits at a corridor's
// junction or wide spot and makes a small "room" there, which people see as part of the corridor; a
// real small room has a door narrower than itself, or opens into other rooms
// (a suite), and stays. No opening counts at a `closed` vertex (a cut ag-cut
// made on a door or wall gap it closed, ClosedVertices). A folded area takes
// the kind of the area it joins.
void FoldCorridorPieces(const proto::CutGraph& graph, const PlanModel& model,
                        const std::vector<bool>& closed, double max_m2, AreaPlan* plan);

}  // namespace areagraph

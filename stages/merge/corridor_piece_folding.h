#pragma once

#include "proto/artifacts.pb.h"
#include "stages/merge/area_assignment.h"

namespace areagraph {

// A small room area opens into a neighbour without a door when the opening
// at a graph vertex they share is at least this share of the small area's
// median free width: a door is narrower than the room behind it, a piece of
// corridor is as wide as its opening.
inline constexpr double kPieceOpeningShare = 0.9;
// A piece of corridor opens widely to both sides (or more, at a junction);
// a room with one wide opening is a room with an open front.
inline constexpr int kMinWideOpenings = 2;

// Folds room areas smaller than `max_m2` (their edges' polygons) that have
// at least kMinWideOpenings openings (at graph vertices) into corridors at
// least kPieceOpeningShare of their own median free width wide, into the
// corridor behind the widest one. A corridor here is a room-less area or a
// room area covering at least kCorridorElongation squares (room_joining.h) of its median free
// width. The room disk (W) fits at a corridor's junction or wide spot and
// makes a small "room" there, which people see as part of the corridor; a
// real small room has a door narrower than itself, or opens into other rooms
// (a suite), and stays. With `keep_closed_doors` no opening counts at a cut
// ag-cut made on a door or wall gap it closed. A folded area takes the kind
// of the area it joins.
void FoldCorridorPieces(const proto::CutGraph& graph, double resolution_m, double max_m2,
                        bool keep_closed_doors, AreaPlan* plan);

}  // namespace areagraph

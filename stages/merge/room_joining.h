#pragma once

#include "proto/artifacts.pb.h"
#include "stages/merge/area_assignment.h"

namespace areagraph {

// An opening separates two rooms only when it is narrower than this share
// of the free width on both of its sides (the widest within kSideReachM of
// it). Chosen on the generated tuning floors and the real maps (0.9).
inline constexpr double kDoorWidthShare = 0.9;
// How far into each area the width beside an opening is looked for (metres).
inline constexpr double kSideReachM = 1.5;

// A room area whose room shape covers at least this many squares of its
// median free width is shaped like a corridor. Chosen on the real maps and
// the tuning floors (4 loses Freiburg52_scan furnished again; 6 and 10 the
// same).
inline constexpr double kCorridorElongation = 6;

// Whether a room area is shaped like a corridor: its room shape's area is
// at least kCorridorElongation squares of its median free width.
bool CorridorLike(const proto::CutGraph& graph, const AreaPlan::Area& area);

// Joins room areas that meet at a graph vertex without a narrowing between
// them: the opening there is not narrower than kDoorWidthShare of the space
// on the narrower side. The room disk stopped there (at a piece of furniture
// or a bend), but nothing divides the room; a door is narrower than the
// rooms it joins. (A second cue, how deep the narrowing is, separated
// furniture gaps from doors on the generated floors but merged real rooms
// on the scanned maps, whose doorways are deep: dropped, see
// docs/quality.md.) With `keep_closed_doors`, rooms that meet at a cut
// ag-cut made on a door or wall gap it closed (PassagePoint.closed_by_cut)
// stay apart: their jambs are walls. Not when both rooms are shaped like
// corridors (kCorridorElongation): the cut's thin wall end is then the
// corner where one corridor meets another.
void JoinRoomsWithoutDoors(const proto::CutGraph& graph, double resolution_m,
                           bool keep_closed_doors, AreaPlan* plan);

}  // namespace areagraph

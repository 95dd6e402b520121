#pragma once

#include <Eigen/Core>
#include <functional>
#include <vector>

#include "stages/cut/closed_passages.h"
#include "stages/cut/edge_track.h"

namespace areagraph {

// A stretch of an edge that lies in one room (-1: in none).
struct EdgePiece {
  PathPosition begin;
  PathPosition end;
  int room = -1;
};

// How one edge should be cut (the paper's Alg. 3 plus cleanup):
// 1. The path is split wherever the room under it changes (the crossing is
//    found by sampling and bisection along the segment).
// 2. A dead-end edge shorter than `room_width_px` is not cut; it takes the
//    room found at its junction end. Likewise a piece shorter than W at a
//    dead end joins its neighbour. Neither happens where the cut lies on
//    one of `closed_lines` (cut pass KEEP_CLOSED_ROOM_TIPS): a small room behind
//    a door the cut closed is shorter than W, not a bulge of the corridor.
// 3. A room-less piece shorter than W between two rooms is a doorway: it
//    vanishes, leaving one cut at its narrowest point (or none when both
//    sides are the same room).
// 4. A cut between a room and a longer room-less stretch moves to the
//    narrowest point of that stretch within W of it (usually the door).
// Returns the pieces in path order; they cover the whole edge.
std::vector<EdgePiece> PlanEdgeCuts(const EdgeTrack& track, bool source_is_dead_end,
                                    bool target_is_dead_end, double room_width_px,
                                    const std::function<int(const Eigen::Vector2d&)>& room_at,
                                    const ClosedLines* closed_lines = nullptr);

// The middle of the narrowest stretch of the path between two positions:
// the run of path points (and the two ends) within half a pixel of the
// smallest clearance that holds the minimum.
PathPosition NarrowestPosition(const EdgeTrack& track, const PathPosition& from,
                               const PathPosition& to);

}  // namespace areagraph

#pragma once

#include <vector>

#include "stages/cut/cut_planning.h"
#include "stages/cut/edge_track.h"

namespace areagraph {

// What makes the end of a room's edge a narrow tail (cut pass CUT_NARROW_TAILS).
// The tail is the stretch before the dead end where the clearance stays at
// most the room's widest clearance on the edge over kCorridorWidthRatio
// (stages/geometry/corridor_shape.h): clearly narrower than the room, as a
// side branch is than its corridor. It begins where the free width first
// comes within SteadyWidthSpreadM of the tail's median width
// (stages/cut/width_estimate.h: a corridor's steady width, with scan noise
// on its walls).

// Where a room's piece of an edge runs on into a dead end through a narrow
// tail (a corridor narrower than the room but wider than W, so the room
// disk fills it too; long like a corridor: kCorridorElongation squares of
// its width, stages/geometry/corridor_shape.h), the piece is cut
// where the tail begins and the tail
// becomes a room-less piece: its own area, as a corridor narrower than W
// would be. `pieces` is PlanEdgeCuts' plan of `track`; only pieces at a
// dead end are looked at. The paper has no such cut.
// `resolution_m`: metres per pixel of the track.
void CutNarrowTails(const EdgeTrack& track, bool source_is_dead_end, bool target_is_dead_end,
                    double resolution_m, std::vector<EdgePiece>* pieces);

}  // namespace areagraph

#pragma once

#include "proto/artifacts.pb.h"
#include "stages/merge/area_assignment.h"

namespace areagraph {

// Joins room-less areas (corridor pieces and dead ends) made of uniform
// edges only (nothing along the edge narrows its median clearance,
// NarrowsCorridor in stages/geometry/corridor_shape.h, as a door on the way
// does; a stub in front of a door that a piece took over counts as
// uniform: its narrowing is the door's) where exactly two of them meet at a
// graph vertex (where three or more meet, corridors fork: a place of its own): the Voronoi graph
// cuts a corridor into a piece per junction (every side door, every bend), which people see as one
// corridor. A piece with a constriction (a door into a closet, a door across the corridor) stays
// apart, and rooms are never joined (joining rooms through passages that look open merged real
// rooms on the benchmark). The joined area is a corridor unless all its pieces were dead ends.
void JoinCorridorPieces(const proto::CutGraph& graph, AreaPlan* plan);

}  // namespace areagraph

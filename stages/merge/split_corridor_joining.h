#pragma once

#include <vector>

#include "proto/artifacts.pb.h"
#include "stages/geometry/cell_grid.h"
#include "stages/merge/area_assignment.h"

namespace areagraph {

// The constants of JoinSplitCorridors, chosen on the generated tuning and
// tuning-extra floors and the real maps (areagraph/, RobotMap, bormann/;
// docs/quality.md, "Options beyond the paper").
struct SplitCorridorParams {
  // How far a corridor bends between two of its pieces (degrees). Seen
  // from the vertex, the two pieces' centroids are at least 180 minus this
  // apart (a corridor goes on, bending little; a room across from a side
  // corridor's end is off to the side, at about 90 degrees).
  double bend_deg = 30;
};

// Joins pairs of areas (rooms or room-less pieces) that meet at a graph
// vertex that is not `closed` (ClosedVertices), where the two are pieces of
// one corridor by the constants above, both at least twice `robot_width_m`
// wide (median free width; CleanedMap.robot_width_m, a body's width: two
// people pass each other in a corridor, and rows of cluttered cubicles 0.9 m
// wide with a gap in their partition are no corridor) (and do not narrow where they meet,
// NarrowsCorridor, stages/geometry/corridor_shape.h) and together are shaped like a corridor
// (IsCorridorShaped of the two as one: the wider typical and widest width,
// the sum of their sizes), or belong to a chain of such pairs that is (a
// corridor that W split into three or four short pieces is long only as a
// whole), repeatedly until no pair joins (a corridor
// split into three or four pieces). With an automatic W near or above a corridor's
// width the room disk stops at every slight narrowing and the corridor
// falls into room-shaped pieces; room-less pieces stay apart where a side
// corridor or a doorway's stub forks off (JoinCorridorPieces joins only two
// uniform pieces). A joined area keeps the kind and room of its first piece.
// `grid`, when given, lets an opening that narrows the wider piece's median
// free width join anyway when it is one-sided (a flat wall on one side,
// stages/merge/one_sided_narrowing.h: a cabinet against one wall of a
// corridor). The plan changes while the pass runs: each round
// measures it again (MeasurePlan).
void JoinSplitCorridors(const proto::CutGraph& graph, double resolution_m, double robot_width_m,
                        const std::vector<bool>& closed, AreaPlan* plan,
                        const SplitCorridorParams& params = {}, const CellGrid* grid = nullptr);

}  // namespace areagraph

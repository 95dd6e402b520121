#pragma once

#include "stages/prune/chain_graph.h"

namespace areagraph {

// Whether all sites on one side of the edge are one obstacle cell or cells
// touching it (its 8-neighbours): the edge is then part of the boundary of
// that cell's Voronoi face, a spur that a convex corner (a step of a slanted
// wall, the end of a wall) sends into the free space, however long it is.
bool IsCornerSpur(const ChainEdge& edge);

// One pass of dead-end removal (the paper's Alg. 2): every dead-end edge
// shorter than `max_length_px`, and every dead-end corner spur (see
// IsCornerSpur), is removed, shortest first, and its polygon
// (with whatever it had absorbed) goes to the next edge clockwise around its
// junction, or to the previous one when the next is itself a dead end. The
// last edge of a connected group is never removed. Returns how many went.
int RemoveShortDeadEnds(ChainGraph* graph, double max_length_px);

// Merges junctions that are too close (the paper's last Topology Graph step):
// an edge between two junctions that is shorter than the clearance of either
// end lies inside one free disk, so it is contracted into the end with more
// clearance: the other edges of the dropped junction are extended along it
// to the kept one. Returns the count.
int MergeCloseJunctions(ChainGraph* graph);

}  // namespace areagraph

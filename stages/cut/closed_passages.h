#pragma once

#include "proto/artifacts.pb.h"
#include "stages/geometry/edge_polygon.h"

namespace areagraph {

// A passage point this close (metres) to a site that ag-cut added to close
// a door or a wall gap lies on that closed line. The sites are about one
// per pixel along the line and the cut lies where the edge crosses it (or
// at the narrowest point next to it), so a few cells are enough.
inline constexpr double kClosedPassageReachM = 0.15;

// Marks the passage points of `graph` that lie on a line ag-cut closed on
// purpose (`closing_sites`: the sites of cut.close_wall_doors and
// cut.close_wall_gaps_max_m), so that ag-merge's room joining does not join
// the two rooms again (PassagePoint.closed_by_cut).
void MarkClosedPassages(const PointList& closing_sites, double resolution_m,
                        proto::CutGraph* graph);

}  // namespace areagraph

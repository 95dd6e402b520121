#pragma once

#include <map>
#include <vector>

#include "proto/artifacts.pb.h"
#include "stages/geometry/edge_polygon.h"
#include "stages/geometry/same_width.h"
#include "stages/merge/area_assignment.h"

namespace areagraph {

// An opening within kSameWidthShare (stages/geometry/same_width.h) of the
// free width beside it, at least 1 - kSameWidthShare of it, is no door: the
// space goes on through it, where a door is narrower than the room it opens
// into. Every pass that tells a door from an open side asks this (room
// joining, bay and corridor-piece folding, small closed rooms).

// An area's narrowest opening at a graph vertex: the two sites beside its
// edge ends there (the jambs) and their distance.
struct VertexOpening {
  double width_px = 0;
  Eigen::Vector2d left, right;
};

// Every area's narrowest opening at every vertex its edges reach: per
// vertex, area -> opening.
std::vector<std::map<int, VertexOpening>> OpeningsAtVertices(const proto::CutGraph& graph,
                                                             const AreaPlan& plan);

// Per graph vertex, whether ag-cut made it on a door or wall gap it closed
// on purpose (PassagePoint.closed_by_cut): no merge pass joins areas there.
std::vector<bool> ClosedVertices(const proto::CutGraph& graph);

}  // namespace areagraph

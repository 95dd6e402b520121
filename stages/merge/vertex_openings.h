#pragma once

#include <map>
#include <vector>

#include "proto/artifacts.pb.h"
#include "stages/geometry/edge_polygon.h"
#include "stages/merge/area_assignment.h"

namespace areagraph {

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

}  // namespace areagraph

#pragma once

#include <gtest/gtest.h>

#include <vector>

#include "proto/artifacts.pb.h"
#include "stages/merge/area_assignment.h"

namespace areagraph::testing {

// Small CutGraphs drawn by hand for the merge steps, which read only the
// vertices' kinds, positions and clearances and the edges' ends, rooms,
// lengths, clearances and sites: a graph with just those fields set.

// Short names for the kinds that the tests spell out again and again.
using proto::AREA_CORRIDOR;
using proto::AREA_DEAD_END;
using proto::AREA_ROOM;
using proto::VERTEX_DEAD_END;
using proto::VERTEX_JUNCTION;
using proto::VERTEX_PASSAGE;

// Adds a vertex and returns its index (which is also its id).
inline int AddVertex(proto::CutGraph* graph, proto::VertexKind kind, double clearance_px = 0,
                     double x = 0, double y = 0) {
  proto::GraphVertex* vertex = graph->add_vertices();
  vertex->set_id(graph->vertices_size() - 1);
  vertex->set_kind(kind);
  vertex->set_clearance_px(clearance_px);
  vertex->mutable_position()->set_x(x);
  vertex->mutable_position()->set_y(y);
  return vertex->id();
}

// Adds an edge from `source` to `target` in room `room_id` (-1: none) and
// returns it, for the caller to fill in what the step under test reads.
inline proto::GraphEdge* AddEdge(proto::CutGraph* graph, int source, int target, int room_id = -1,
                                 double length_px = 10) {
  proto::GraphEdge* edge = graph->add_edges();
  edge->set_id(graph->edges_size() - 1);
  edge->set_source(source);
  edge->set_target(target);
  edge->set_room_id(room_id);
  edge->set_length_px(length_px);
  return edge;
}

// An area that a test expects in an AreaPlan.
struct ExpectedArea {
  proto::AreaKind kind;
  int room_id;
  std::vector<int> edges;
};

// `plan` has exactly these areas, in this order, and this area_of_edge.
inline void ExpectPlan(const AreaPlan& plan, const std::vector<ExpectedArea>& areas,
                       const std::vector<int>& area_of_edge) {
  ASSERT_EQ(plan.areas.size(), areas.size());
  for (size_t k = 0; k < areas.size(); ++k) {
    EXPECT_EQ(plan.areas[k].kind, areas[k].kind) << "area " << k;
    EXPECT_EQ(plan.areas[k].room_id, areas[k].room_id) << "area " << k;
    EXPECT_EQ(plan.areas[k].edges, areas[k].edges) << "area " << k;
  }
  EXPECT_EQ(plan.area_of_edge, area_of_edge);
}

}  // namespace areagraph::testing

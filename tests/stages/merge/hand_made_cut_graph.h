#pragma once

#include <gtest/gtest.h>

#include <Eigen/Core>
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

// Adds a straight edge from `source` to `target` along the segment `from` ->
// `to` (px) in room `room_id` (-1: none): path points at both ends and the
// middle, each with clearance `half_width` (or `clearance`, one per point,
// when given), sites `opening_source` / `opening_target` px apart across its
// first and last segment, and a polygon that is the box `half_width` px
// either side of the segment.
inline proto::GraphEdge* AddStraightEdge(proto::CutGraph* graph, int source, int target,
                                         int room_id, Eigen::Vector2d from, Eigen::Vector2d to,
                                         double half_width, double opening_source,
                                         double opening_target,
                                         std::vector<double> clearance = {}) {
  const double length = (to - from).norm();
  proto::GraphEdge* edge = AddEdge(graph, source, target, room_id, length);
  const Eigen::Vector2d along = (to - from) / length;
  const Eigen::Vector2d across(-along.y(), along.x());
  if (clearance.empty()) clearance.assign(3, half_width);
  for (int i = 0; i < 3; ++i) {
    const Eigen::Vector2d p = from + (to - from) * (i / 2.0);
    proto::Point2* point = edge->add_path();
    point->set_x(p.x());
    point->set_y(p.y());
    edge->add_clearance_px(clearance[i]);
  }
  for (int s = 0; s < 2; ++s) {
    const Eigen::Vector2d at = s == 0 ? from : to;
    const double half = (s == 0 ? opening_source : opening_target) / 2;
    proto::Point2* left = edge->add_left_sites();
    left->set_x(at.x() + across.x() * half);
    left->set_y(at.y() + across.y() * half);
    proto::Point2* right = edge->add_right_sites();
    right->set_x(at.x() - across.x() * half);
    right->set_y(at.y() - across.y() * half);
  }
  proto::Ring* ring = edge->mutable_polygon()->mutable_outer();
  const Eigen::Vector2d side = across * half_width;
  for (const Eigen::Vector2d& corner : {Eigen::Vector2d(from - side), Eigen::Vector2d(to - side),
                                        Eigen::Vector2d(to + side), Eigen::Vector2d(from + side)}) {
    proto::Point2* point = ring->add_points();
    point->set_x(corner.x());
    point->set_y(corner.y());
  }
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

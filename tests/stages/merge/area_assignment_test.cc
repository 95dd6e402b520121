// AssignAreas on hand-made cut graphs: one area per room, one per room-less
// edge, and stubs in front of doors joined to the corridor at their junction.
#include "stages/merge/area_assignment.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "stages/geometry/edge_polygon.h"
#include "stages/geometry/ring_points.h"
#include "stages/geometry/ring_simplicity.h"
#include "tests/stages/merge/hand_made_cut_graph.h"

namespace areagraph::testing {
namespace {

TEST(AreaAssignmentTest, OneAreaPerRoomAndPerRoomlessEdge) {
  proto::CutGraph graph;
  const int a = AddVertex(&graph, VERTEX_JUNCTION, 10);
  const int b = AddVertex(&graph, VERTEX_JUNCTION, 10);
  const int end = AddVertex(&graph, VERTEX_DEAD_END, 5);
  const int door = AddVertex(&graph, VERTEX_PASSAGE, 8);
  const int c = AddVertex(&graph, VERTEX_JUNCTION, 10);
  AddEdge(&graph, a, b, /*room_id=*/3, 50);
  AddEdge(&graph, a, end, -1, 40);
  AddEdge(&graph, b, door, -1, 100);  // junction to passage, but too long for a stub
  AddEdge(&graph, door, c, 3, 50);    // room 3 again, apart from edge 0
  AddEdge(&graph, c, c, -1, 30);      // a loop
  AddEdge(&graph, b, c, 5, 20);
  ExpectPlan(AssignAreas(graph),
             {{AREA_ROOM, 3, {0, 3}},
              {AREA_DEAD_END, -1, {1}},
              {AREA_CORRIDOR, -1, {2}},
              {AREA_CORRIDOR, -1, {4}},
              {AREA_ROOM, 5, {5}}},
             {0, 1, 2, 0, 3, 4});
}

// A junction with a stub to a door, a corridor, a dead end and a longer
// room edge; the stub is `stub_px` long, the clearances add up to 18 px.
proto::CutGraph StubAtAJunction(double stub_px) {
  proto::CutGraph graph;
  const int junction = AddVertex(&graph, VERTEX_JUNCTION, 10);
  const int door = AddVertex(&graph, VERTEX_PASSAGE, 8);
  const int far = AddVertex(&graph, VERTEX_JUNCTION, 10);
  const int end = AddVertex(&graph, VERTEX_DEAD_END, 4);
  const int room = AddVertex(&graph, VERTEX_JUNCTION, 20);
  AddEdge(&graph, door, junction, -1, stub_px);  // passage to junction: either way round
  AddEdge(&graph, junction, far, -1, 100);
  AddEdge(&graph, junction, end, -1, 40);
  AddEdge(&graph, junction, room, 1, 200);
  AddEdge(&graph, door, room, 2, 30);  // the room behind the door
  return graph;
}

TEST(AreaAssignmentTest, StubJoinsTheLongestRoomlessEdgeAtItsJunction) {
  // As long as both clearances together: still a stub.
  ExpectPlan(AssignAreas(StubAtAJunction(18)),
             {{AREA_CORRIDOR, -1, {0, 1}},
              {AREA_DEAD_END, -1, {2}},
              {AREA_ROOM, 1, {3}},
              {AREA_ROOM, 2, {4}}},
             {0, 0, 1, 2, 3});
}

TEST(AreaAssignmentTest, EdgeLongerThanBothClearancesIsNoStub) {
  ExpectPlan(AssignAreas(StubAtAJunction(18.5)),
             {{AREA_CORRIDOR, -1, {0}},
              {AREA_CORRIDOR, -1, {1}},
              {AREA_DEAD_END, -1, {2}},
              {AREA_ROOM, 1, {3}},
              {AREA_ROOM, 2, {4}}},
             {0, 1, 2, 3, 4});
}

TEST(AreaAssignmentTest, StubAmongRoomEdgesOnlyJoinsTheLongestOne) {
  proto::CutGraph graph;
  const int junction = AddVertex(&graph, VERTEX_JUNCTION, 10);
  const int door = AddVertex(&graph, VERTEX_PASSAGE, 8);
  const int a = AddVertex(&graph, VERTEX_JUNCTION, 10);
  const int b = AddVertex(&graph, VERTEX_JUNCTION, 10);
  AddEdge(&graph, junction, door, -1, 5);
  AddEdge(&graph, junction, a, 4, 30);
  AddEdge(&graph, junction, b, 7, 60);
  ExpectPlan(AssignAreas(graph), {{AREA_ROOM, 7, {0, 2}}, {AREA_ROOM, 4, {1}}}, {0, 1, 0});
}

TEST(AreaAssignmentTest, StubJoiningADeadEndMakesADeadEnd) {
  proto::CutGraph graph;
  const int junction = AddVertex(&graph, VERTEX_JUNCTION, 10);
  const int door = AddVertex(&graph, VERTEX_PASSAGE, 8);
  const int end = AddVertex(&graph, VERTEX_DEAD_END, 3);
  AddEdge(&graph, junction, door, -1, 5);
  AddEdge(&graph, junction, end, -1, 25);
  ExpectPlan(AssignAreas(graph), {{AREA_DEAD_END, -1, {0, 1}}}, {0, 0});
}

TEST(AreaAssignmentTest, StubAloneAtItsJunctionStaysAnArea) {
  proto::CutGraph graph;
  AddEdge(&graph, AddVertex(&graph, VERTEX_JUNCTION, 10), AddVertex(&graph, VERTEX_PASSAGE, 8), -1,
          5);
  ExpectPlan(AssignAreas(graph), {{AREA_CORRIDOR, -1, {0}}}, {0});
}

TEST(AreaAssignmentTest, OnlyJunctionToPassageEdgesOutsideRoomsAreStubs) {
  proto::CutGraph graph;
  const int junction = AddVertex(&graph, VERTEX_JUNCTION, 10);
  const int other = AddVertex(&graph, VERTEX_JUNCTION, 10);
  const int door = AddVertex(&graph, VERTEX_PASSAGE, 8);
  const int door2 = AddVertex(&graph, VERTEX_PASSAGE, 8);
  const int far = AddVertex(&graph, VERTEX_JUNCTION, 10);
  AddEdge(&graph, junction, far, -1, 100);
  AddEdge(&graph, junction, other, -1, 1);  // junction to junction
  AddEdge(&graph, door, door2, -1, 1);      // passage to passage
  AddEdge(&graph, junction, door2, 6, 1);   // in a room
  ExpectPlan(AssignAreas(graph),
             {{AREA_CORRIDOR, -1, {0}},
              {AREA_CORRIDOR, -1, {1}},
              {AREA_CORRIDOR, -1, {2}},
              {AREA_ROOM, 6, {3}}},
             {0, 1, 2, 3});
}

TEST(AreaAssignmentTest, EmptyGraphHasNoAreas) {
  ExpectPlan(AssignAreas(proto::CutGraph()), {}, {});
}

TEST(AreaAssignmentTest, MergeIntoMovesEdgesAndRenumbersLaterAreas) {
  AreaPlan plan;
  plan.areas = {{AREA_ROOM, 2, {0, 4}},
                {AREA_CORRIDOR, -1, {1}},
                {AREA_ROOM, 5, {2, 5}},
                {AREA_DEAD_END, -1, {3}}};
  plan.area_of_edge = {0, 1, 2, 3, 0, 2};
  plan.MergeInto(1, 3);  // into a later area
  ExpectPlan(plan, {{AREA_ROOM, 2, {0, 4}}, {AREA_ROOM, 5, {2, 5}}, {AREA_DEAD_END, -1, {1, 3}}},
             {0, 2, 1, 2, 0, 1});
  plan.MergeInto(2, 0);  // into an earlier one
  ExpectPlan(plan, {{AREA_ROOM, 2, {0, 1, 3, 4}}, {AREA_ROOM, 5, {2, 5}}}, {0, 0, 1, 0, 0, 1});
}

}  // namespace
}  // namespace areagraph::testing

namespace areagraph::testing {
namespace {

// AreaSizesM2 sums half of each ring's TwiceSignedArea: the value
// SignedArea(RingPoints(...)) gives, to the bit, on random rings.
TEST(AreaAssignmentTest, AreaSizesAsSignedAreasOfThePolygons) {
  std::mt19937 random(5);
  std::uniform_real_distribution<double> coordinate(-300.0, 900.0);
  auto random_ring = [&](proto::Ring* ring) {
    const int n = std::uniform_int_distribution<int>(0, 12)(random);
    for (int i = 0; i < n; ++i) {
      proto::Point2* point = ring->add_points();
      point->set_x(coordinate(random));
      point->set_y(coordinate(random));
    }
  };
  proto::CutGraph graph;
  AreaPlan plan;
  plan.areas.resize(4);
  for (int e = 0; e < 60; ++e) {
    proto::GraphEdge* edge = graph.add_edges();
    random_ring(edge->mutable_polygon()->mutable_outer());
    for (int k = 0; k < e % 3; ++k) random_ring(edge->add_absorbed()->mutable_outer());
    plan.area_of_edge.push_back(e % 4);
  }
  const double resolution_m = 0.05, cell_m2 = resolution_m * resolution_m;
  std::vector<double> want(4, 0);
  for (int e = 0; e < graph.edges_size(); ++e) {
    double& area = want[plan.area_of_edge[e]];
    area += cell_m2 * std::abs(SignedArea(RingPoints(graph.edges(e).polygon().outer())));
    for (const proto::Polygon& absorbed : graph.edges(e).absorbed()) {
      area += cell_m2 * std::abs(SignedArea(RingPoints(absorbed.outer())));
    }
  }
  const std::vector<double> got = AreaSizesM2(graph, plan, resolution_m);
  ASSERT_EQ(got.size(), want.size());
  for (size_t k = 0; k < want.size(); ++k) {
    EXPECT_EQ(got[k], want[k]) << "area " << k;
    EXPECT_GT(got[k], 0);
  }
}

}  // namespace
}  // namespace areagraph::testing

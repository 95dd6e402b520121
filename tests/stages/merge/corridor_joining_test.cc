// JoinCorridorPieces on hand-made cut graphs: uniform room-less pieces that
// meet two at a vertex become one area; forks, doors and rooms stay apart.
#include "stages/merge/corridor_joining.h"

#include <gtest/gtest.h>

#include "tests/stages/merge/hand_made_cut_graph.h"

namespace areagraph::testing {
namespace {

// Clearance along an edge whose width never drops below the median's 3/4.
const std::vector<double> kUniform = {10, 9, 10, 11, 10};
// A door on the way: 4 px against a median of 10.
const std::vector<double> kDoor = {10, 10, 4, 10, 10};

void AddPiece(proto::CutGraph* graph, int source, int target, const std::vector<double>& clearance,
              int room_id = -1) {
  proto::GraphEdge* edge = AddEdge(graph, source, target, room_id);
  for (double c : clearance) edge->add_clearance_px(c);
}

// One area per edge, of the given kinds (rooms numbered by their edge).
AreaPlan OneAreaPerEdge(const std::vector<proto::AreaKind>& kinds) {
  AreaPlan plan;
  for (size_t e = 0; e < kinds.size(); ++e) {
    plan.areas.push_back(
        {kinds[e], kinds[e] == AREA_ROOM ? static_cast<int>(e) : -1, {static_cast<int>(e)}});
    plan.area_of_edge.push_back(static_cast<int>(e));
  }
  return plan;
}

// Two room-less pieces of `kind` through a vertex of kind `middle`, their far
// ends of kind `ends`, the second with `clearance`, after JoinCorridorPieces.
AreaPlan JoinTwoPieces(proto::VertexKind middle, proto::VertexKind ends, proto::AreaKind kind,
                       const std::vector<double>& clearance) {
  proto::CutGraph graph;
  const int vertex = AddVertex(&graph, middle);
  AddPiece(&graph, AddVertex(&graph, ends), vertex, kUniform);
  AddPiece(&graph, vertex, AddVertex(&graph, ends), clearance);
  AreaPlan plan = OneAreaPerEdge({kind, kind});
  JoinCorridorPieces(graph, &plan);
  return plan;
}

TEST(CorridorJoiningTest, CorridorCutAtSideDoorsBecomesOneCorridor) {
  // end - a - b - end along the corridor; a room edge leaves a and b.
  proto::CutGraph graph;
  const int left_end = AddVertex(&graph, VERTEX_DEAD_END);
  const int a = AddVertex(&graph, VERTEX_JUNCTION);
  const int b = AddVertex(&graph, VERTEX_JUNCTION);
  const int right_end = AddVertex(&graph, VERTEX_DEAD_END);
  const int room = AddVertex(&graph, VERTEX_JUNCTION);
  AddPiece(&graph, left_end, a, kUniform);
  AddPiece(&graph, a, b, kUniform);
  AddPiece(&graph, b, right_end, kUniform);
  AddPiece(&graph, a, room, kUniform, 3);
  AddPiece(&graph, b, room, kUniform, 4);
  AreaPlan plan =
      OneAreaPerEdge({AREA_DEAD_END, AREA_CORRIDOR, AREA_DEAD_END, AREA_ROOM, AREA_ROOM});
  JoinCorridorPieces(graph, &plan);
  ExpectPlan(plan, {{AREA_CORRIDOR, -1, {0, 1, 2}}, {AREA_ROOM, 3, {3}}, {AREA_ROOM, 4, {4}}},
             {0, 0, 0, 1, 2});
}

TEST(CorridorJoiningTest, PiecesMeetingAtAPassagePointAreJoinedWhenNeitherNarrows) {
  ExpectPlan(JoinTwoPieces(VERTEX_PASSAGE, VERTEX_JUNCTION, AREA_CORRIDOR, kUniform),
             {{AREA_CORRIDOR, -1, {0, 1}}}, {0, 0});
}

TEST(CorridorJoiningTest, DeadEndsOnlyStayADeadEnd) {
  ExpectPlan(JoinTwoPieces(VERTEX_JUNCTION, VERTEX_DEAD_END, AREA_DEAD_END, kUniform),
             {{AREA_DEAD_END, -1, {0, 1}}}, {0, 0});
}

TEST(CorridorJoiningTest, ThreePiecesAtAForkStayApart) {
  proto::CutGraph graph;
  const int fork = AddVertex(&graph, VERTEX_JUNCTION);
  for (int k = 0; k < 3; ++k) AddPiece(&graph, fork, AddVertex(&graph, VERTEX_JUNCTION), kUniform);
  AreaPlan plan = OneAreaPerEdge({AREA_CORRIDOR, AREA_CORRIDOR, AREA_CORRIDOR});
  JoinCorridorPieces(graph, &plan);
  ExpectPlan(plan, {{AREA_CORRIDOR, -1, {0}}, {AREA_CORRIDOR, -1, {1}}, {AREA_CORRIDOR, -1, {2}}},
             {0, 1, 2});
}

TEST(CorridorJoiningTest, PieceWithADoorStaysApartAndDoesNotCountAtAFork) {
  // At the fork: two uniform pieces and one with a door; at its far end the
  // door piece meets one more uniform piece.
  proto::CutGraph graph;
  const int fork = AddVertex(&graph, VERTEX_JUNCTION);
  const int behind_door = AddVertex(&graph, VERTEX_JUNCTION);
  AddPiece(&graph, fork, AddVertex(&graph, VERTEX_JUNCTION), kUniform);
  AddPiece(&graph, fork, behind_door, kDoor);
  AddPiece(&graph, fork, AddVertex(&graph, VERTEX_JUNCTION), kUniform);
  AddPiece(&graph, behind_door, AddVertex(&graph, VERTEX_DEAD_END), kUniform);
  AreaPlan plan = OneAreaPerEdge({AREA_CORRIDOR, AREA_CORRIDOR, AREA_CORRIDOR, AREA_DEAD_END});
  JoinCorridorPieces(graph, &plan);
  ExpectPlan(plan,
             {{AREA_CORRIDOR, -1, {0, 2}}, {AREA_CORRIDOR, -1, {1}}, {AREA_DEAD_END, -1, {3}}},
             {0, 1, 0, 2});
}

TEST(CorridorJoiningTest, OneNarrowingEdgeMakesTheWholeAreaStayApart) {
  // Area 0 has a uniform edge and one with a door; area 1 meets it at `a`.
  proto::CutGraph graph;
  const int a = AddVertex(&graph, VERTEX_JUNCTION);
  const int b = AddVertex(&graph, VERTEX_JUNCTION);
  AddPiece(&graph, a, b, kUniform);
  AddPiece(&graph, b, AddVertex(&graph, VERTEX_JUNCTION), kDoor);
  AddPiece(&graph, a, AddVertex(&graph, VERTEX_JUNCTION), kUniform);
  AreaPlan plan;
  plan.areas = {{AREA_CORRIDOR, -1, {0, 1}}, {AREA_CORRIDOR, -1, {2}}};
  plan.area_of_edge = {0, 0, 1};
  JoinCorridorPieces(graph, &plan);
  ExpectPlan(plan, {{AREA_CORRIDOR, -1, {0, 1}}, {AREA_CORRIDOR, -1, {2}}}, {0, 0, 1});
}

TEST(CorridorJoiningTest, UniformMeansNothingBelowTheMedianOverTheCorridorWidthRatio) {
  // Median 10: the least clearance that is no narrowing is 10 / 1.3 = 7.69.
  for (const auto& [lowest, joined] : {std::pair{7.7, true}, std::pair{7.6, false}}) {
    const AreaPlan plan =
        JoinTwoPieces(VERTEX_JUNCTION, VERTEX_JUNCTION, AREA_CORRIDOR, {10, lowest, 10, 12});
    EXPECT_EQ(plan.areas.size(), joined ? 1u : 2u) << "lowest clearance " << lowest;
  }
}

TEST(CorridorJoiningTest, EdgeWithoutClearancesIsNotUniform) {
  EXPECT_EQ(JoinTwoPieces(VERTEX_JUNCTION, VERTEX_JUNCTION, AREA_CORRIDOR, {}).areas.size(), 2u);
}

TEST(CorridorJoiningTest, RoomsAreNeverJoined) {
  // Two uniform room edges meeting at a vertex, and a room meeting a corridor.
  proto::CutGraph graph;
  const int a = AddVertex(&graph, VERTEX_JUNCTION);
  const int b = AddVertex(&graph, VERTEX_JUNCTION);
  AddPiece(&graph, AddVertex(&graph, VERTEX_JUNCTION), a, kUniform, 0);
  AddPiece(&graph, a, AddVertex(&graph, VERTEX_JUNCTION), kUniform, 1);
  AddPiece(&graph, AddVertex(&graph, VERTEX_JUNCTION), b, kUniform, 2);
  AddPiece(&graph, b, AddVertex(&graph, VERTEX_JUNCTION), kUniform);
  AreaPlan plan = OneAreaPerEdge({AREA_ROOM, AREA_ROOM, AREA_ROOM, AREA_CORRIDOR});
  JoinCorridorPieces(graph, &plan);
  ExpectPlan(
      plan,
      {{AREA_ROOM, 0, {0}}, {AREA_ROOM, 1, {1}}, {AREA_ROOM, 2, {2}}, {AREA_CORRIDOR, -1, {3}}},
      {0, 1, 2, 3});
}

}  // namespace
}  // namespace areagraph::testing

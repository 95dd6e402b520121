// The merge's pass table (stages/merge/merge_passes.h): every pass once, in
// the order paper.pbtxt skips them (each pass's drawn case is in
// merge_pass_cases_test.cc); the passes without a test file of their own are
// tested here on hand-made cut graphs: ClosedVertices, FoldOpenBays,
// JoinSplitCorridors and JoinCorridorStems.
#include "stages/merge/merge_passes.h"

#include <gtest/gtest.h>

#include <set>

#include "stages/common/pipeline_options.h"
#include "stages/common/skipped_passes.h"
#include "stages/merge/bay_folding.h"
#include "stages/merge/corridor_stem_joining.h"
#include "stages/merge/split_corridor_joining.h"
#include "stages/merge/vertex_openings.h"
#include "tests/stages/merge/hand_made_cut_graph.h"
#include "tests/support/test_support.h"

namespace areagraph::testing {
namespace {

using Pass = proto::MergeOptions::Pass;
constexpr double kResolutionM = 0.05;
// clean.robot_width_m's default, which the CleanedMap carries.
constexpr double kRobotWidthM = 0.5;

TEST(MergePassTableTest, EveryPassOnceWithAReason) {
  const std::vector<MergePass>& table = MergePassTable();
  std::set<int> seen;
  for (const MergePass& row : table) {
    EXPECT_TRUE(seen.insert(row.pass).second) << MergePassName(row.pass);
    // A join pass, a keep pass, or one whose switch the growth or the
    // passages read.
    EXPECT_TRUE(row.join == nullptr || row.keep == nullptr) << MergePassName(row.pass);
    if (row.join == nullptr && row.keep == nullptr) {
      EXPECT_TRUE(row.pass == proto::MergeOptions::OPEN_BORDER_PASSAGES ||
                  row.pass == proto::MergeOptions::GROWTH_STOPS_AT_NARROW_GAPS)
          << MergePassName(row.pass);
    }
    EXPECT_GT(std::string(row.order).size(), 20u) << MergePassName(row.pass);
  }
  EXPECT_EQ(static_cast<int>(seen.size()), proto::MergeOptions::Pass_descriptor()->value_count());
}

TEST(MergePassTableTest, ThePaperSkipsEveryPassInTheTablesOrder) {
  const proto::PipelineOptions paper = ReadOptionsFile(SourcePath("examples/options/paper.pbtxt"));
  const std::vector<MergePass>& table = MergePassTable();
  ASSERT_EQ(paper.merge().skip_passes_size(), static_cast<int>(table.size()));
  for (size_t k = 0; k < table.size(); ++k) {
    EXPECT_EQ(paper.merge().skip_passes(static_cast<int>(k)), table[k].pass);
    EXPECT_FALSE(RunsStagePass(paper.merge(), table[k].pass));
    EXPECT_TRUE(RunsStagePass(proto::MergeOptions(), table[k].pass));
  }
}

TEST(MergePassTableTest, OptionsOfAPassAreItsOwnMessage) {
  proto::MergeOptions options;
  options.mutable_furniture_gaps()->set_max_elongation(3);
  for (const MergePass& row : MergePassTable()) {
    if (row.options_of == nullptr) continue;
    const google::protobuf::Message* message = row.options_of(options);
    ASSERT_NE(message, nullptr);
    EXPECT_NE(message, &options);
    if (row.pass == proto::MergeOptions::JOIN_FURNITURE_GAPS) {
      EXPECT_EQ(message, &options.furniture_gaps());
    }
  }
}

// Four passage vertices; passage points on three of them (two marked
// closed_by_cut) and on a vertex that does not exist.
TEST(ClosedVerticesTest, OnlyTheMarkedCuts) {
  proto::CutGraph graph;
  for (int k = 0; k < 4; ++k) AddVertex(&graph, VERTEX_PASSAGE, 10, 100 * k, 0);
  for (const auto& [vertex, closed] : {std::pair{1, true}, {2, false}, {3, true}, {9, true}}) {
    proto::PassagePoint* passage = graph.add_passage_points();
    passage->set_vertex(vertex);  // 9: no such vertex, ignored
    passage->set_closed_by_cut(closed);
  }
  EXPECT_EQ(ClosedVertices(graph), (std::vector<bool>{false, true, false, true}));
}

// A room 200 x 120 px (two edges in room 0, meeting at the vertex 1) with a
// room-less area (edge 2) of `length` px and 40 px wide opening off it at
// vertex 2 (x = 200) through an opening `mouth` px wide.
struct RoomWithBay {
  proto::CutGraph graph;
  AreaPlan plan;
};
RoomWithBay BayOf(double length, double mouth) {
  RoomWithBay out;
  proto::CutGraph& graph = out.graph;
  const int a = AddVertex(&graph, VERTEX_DEAD_END, 60, 0, 0);
  const int b = AddVertex(&graph, VERTEX_JUNCTION, 60, 100, 0);
  const int c = AddVertex(&graph, VERTEX_PASSAGE, 20, 200, 0);
  const int d = AddVertex(&graph, VERTEX_DEAD_END, 20, 200 + length, 0);
  AddStraightEdge(&graph, a, b, 0, {0, 0}, {100, 0}, 60, 120, 120);
  AddStraightEdge(&graph, b, c, 0, {100, 0}, {200, 0}, 60, 120, 120);
  // The bay's clearance narrows to half the mouth at the room's side.
  AddStraightEdge(&graph, c, d, -1, {200, 0}, {200 + length, 0}, 20, mouth, 40,
                  {mouth / 2, 20, 20});
  out.plan = AssignAreas(graph);
  return out;
}

TEST(FoldOpenBaysTest, AShortAreaOpenOverItsWidthFoldsIntoTheRoom) {
  RoomWithBay bay = BayOf(60, 40);
  ASSERT_EQ(bay.plan.areas.size(), 2u);
  FoldOpenBays(bay.graph, MeasurePlan(bay.graph, bay.plan, kResolutionM), &bay.plan);
  ExpectPlan(bay.plan, {{AREA_ROOM, 0, {0, 1, 2}}}, {0, 0, 0});
}

TEST(FoldOpenBaysTest, ANarrowerMouthOrALongAreaStaysApart) {
  // A door 20 px wide into the 40 px area: a closet behind a door.
  RoomWithBay closet = BayOf(60, 20);
  FoldOpenBays(closet.graph, MeasurePlan(closet.graph, closet.plan, kResolutionM), &closet.plan);
  EXPECT_EQ(closet.plan.areas.size(), 2u);
  // 300 px long and 40 px wide: a corridor, however wide its mouth.
  RoomWithBay corridor = BayOf(300, 40);
  FoldOpenBays(corridor.graph, MeasurePlan(corridor.graph, corridor.plan, kResolutionM),
               &corridor.plan);
  EXPECT_EQ(corridor.plan.areas.size(), 2u);
}

// Two rooms 120 x 40 px (2 m wide at 0.05 m/px) along y = 0 that meet at
// vertex 1 (x = 120) through an opening as wide as they are: one corridor
// that the room disk split. The vertex is a closed cut when `closed`.
proto::CutGraph SplitCorridor(bool closed) {
  proto::CutGraph graph;
  const int a = AddVertex(&graph, VERTEX_JUNCTION, 20, 0, 0);
  const int cut = AddVertex(&graph, VERTEX_PASSAGE, 20, 120, 0);
  const int b = AddVertex(&graph, VERTEX_JUNCTION, 20, 240, 0);
  AddStraightEdge(&graph, a, cut, 0, {0, 0}, {120, 0}, 20, 40, 40);
  AddStraightEdge(&graph, cut, b, 1, {120, 0}, {240, 0}, 20, 40, 40);
  proto::PassagePoint* passage = graph.add_passage_points();
  passage->set_vertex(cut);
  passage->set_closed_by_cut(closed);
  return graph;
}

TEST(JoinSplitCorridorsTest, TwoPiecesOfOneCorridorJoin) {
  const proto::CutGraph graph = SplitCorridor(false);
  AreaPlan plan = AssignAreas(graph);
  ASSERT_EQ(plan.areas.size(), 2u);
  JoinSplitCorridors(graph, kResolutionM, kRobotWidthM, ClosedVertices(graph), &plan);
  ExpectPlan(plan, {{AREA_ROOM, 0, {0, 1}}}, {0, 0});
}

TEST(JoinSplitCorridorsTest, PiecesStayApartAtAClosedCutOrANarrowing) {
  const proto::CutGraph closed = SplitCorridor(true);
  AreaPlan plan = AssignAreas(closed);
  JoinSplitCorridors(closed, kResolutionM, kRobotWidthM, ClosedVertices(closed), &plan);
  EXPECT_EQ(plan.areas.size(), 2u);
  // A door 20 px wide between the two: a room behind a door in line.
  proto::CutGraph door = SplitCorridor(false);
  for (proto::GraphEdge& edge : *door.mutable_edges()) {
    const bool source_side = edge.source() == 1;
    proto::Point2* left = source_side ? edge.mutable_left_sites(0) : edge.mutable_left_sites(1);
    proto::Point2* right = source_side ? edge.mutable_right_sites(0) : edge.mutable_right_sites(1);
    left->set_y(10);
    right->set_y(-10);
  }
  AreaPlan door_plan = AssignAreas(door);
  JoinSplitCorridors(door, kResolutionM, kRobotWidthM, ClosedVertices(door), &door_plan);
  EXPECT_EQ(door_plan.areas.size(), 2u);
}

// A room-less corridor 300 px long and 40 px wide (two edges from its ends
// to the junction 1 at x = 150) and a branch 20 px wide and 100 px long down
// from that junction to a dead end, opening into it `mouth` px wide.
struct CorridorAndStem {
  proto::CutGraph graph;
  AreaPlan plan;
};
CorridorAndStem StemOf(double mouth) {
  CorridorAndStem out;
  proto::CutGraph& graph = out.graph;
  const int a = AddVertex(&graph, VERTEX_JUNCTION, 20, 0, 0);
  const int j = AddVertex(&graph, VERTEX_JUNCTION, 20, 150, 0);
  const int b = AddVertex(&graph, VERTEX_JUNCTION, 20, 300, 0);
  const int end = AddVertex(&graph, VERTEX_DEAD_END, 10, 150, 120);
  AddStraightEdge(&graph, a, j, -1, {0, 0}, {150, 0}, 20, 40, 40);
  AddStraightEdge(&graph, j, b, -1, {150, 0}, {300, 0}, 20, 40, 40);
  AddStraightEdge(&graph, j, end, -1, {150, 20}, {150, 120}, 10, mouth, 20);
  out.plan.areas = {{AREA_CORRIDOR, -1, {0, 1}}, {AREA_DEAD_END, -1, {2}}};
  out.plan.area_of_edge = {0, 0, 1};
  return out;
}

TEST(JoinCorridorStemsTest, ABranchThatDoesNotNarrowJoinsItsCorridor) {
  CorridorAndStem stem = StemOf(20);
  JoinCorridorStems(stem.graph, MeasurePlan(stem.graph, stem.plan, kResolutionM),
                    ClosedVertices(stem.graph), &stem.plan);
  ExpectPlan(stem.plan, {{AREA_CORRIDOR, -1, {0, 1, 2}}}, {0, 0, 0});
}

TEST(JoinCorridorStemsTest, AClosetBehindANarrowerDoorStaysApart) {
  CorridorAndStem closet = StemOf(12);
  JoinCorridorStems(closet.graph, MeasurePlan(closet.graph, closet.plan, kResolutionM),
                    ClosedVertices(closet.graph), &closet.plan);
  EXPECT_EQ(closet.plan.areas.size(), 2u);
}

}  // namespace
}  // namespace areagraph::testing

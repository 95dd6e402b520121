// Cut's pass table (stages/cut/cut_passes.h): every pass once, in the order
// paper.pbtxt skips them, with a reason, and a case on a constructed map that
// each pass fixes (it fails with the pass skipped); FREE_STANDING_ISLANDS and
// CLOSE_MOUTHS, whose whole-pipeline effect merge's passes also reach, are
// tested here on the Cut Graph.
#include "stages/cut/cut_passes.h"

#include <gtest/gtest.h>

#include <map>
#include <set>

#include "stages/common/pipeline_options.h"
#include "tests/support/area_test_support.h"
#include "tests/support/test_support.h"
#include "tools/example_maps/floor_plan.h"

namespace areagraph::testing {
namespace {

using Pass = proto::CutOptions::Pass;

// Where each pass's case lives: a test on a constructed map that fails when
// the pass is skipped.
const std::map<Pass, const char*>& CaseOfEachPass() {
  static const std::map<Pass, const char*> cases = {
      {proto::CutOptions::WIDTH_ABOVE_DOORS,
       "room_width_test.cc ChooseRoomWidthTest.DoorWiderThanTheCorridorFollowsRoomWidthAboveDoors"},
      {proto::CutOptions::FREE_STANDING_ISLANDS,
       "this file, FreeStandingIslandsTest.TheBlockDoesNotStopTheRoomDisk"},
      {proto::CutOptions::WALL_PIECES_NEED_BOTH_ENDS,
       "pipeline/partition_cabinet_test.cc PartitionCabinetTest.TheRoomIsOneRoomAndOneArea"},
      {proto::CutOptions::CLOSE_WALL_DOORS,
       "pipeline/local_doors_test.cc "
       "LocalDoorsTest.ClosingWallDoorsDividesOfficeFromCorridor"},
      {proto::CutOptions::CLOSE_WALL_GAPS,
       "pipeline/local_doors_test.cc "
       "LocalDoorsTest.DoorWiderThanItsCorridorDividesOfficeFromCorridor"},
      {proto::CutOptions::CLOSE_MOUTHS,
       "this file, CloseMouthsTest.TheRoomDiskStopsAtTheBaysMouth"},
      {proto::CutOptions::SMALL_ROOM_DISK,
       "room_disks_test.cc SmallRoomDiskTest.TheFurnishedOfficeIsOneRoom"},
      {proto::CutOptions::KEEP_CLOSED_ROOM_TIPS,
       "pipeline/small_closed_rooms_test.cc "
       "SmallClosedRoomsTest.AClosetBehindAClosedDoorIsAnAreaOfItsOwn"},
      {proto::CutOptions::CUT_NARROW_TAILS,
       "pipeline/narrow_tail_test.cc NarrowTailTest.TheTailIsItsOwnArea"},
  };
  return cases;
}

TEST(CutPassTableTest, EveryPassOnceWithACaseAndAReason) {
  const std::vector<CutPass>& table = CutPassTable();
  std::set<int> seen;
  for (const CutPass& row : table) {
    EXPECT_TRUE(seen.insert(row.pass).second) << CutPassName(row.pass);
    EXPECT_GT(std::string(row.order).size(), 20u) << CutPassName(row.pass);
    EXPECT_GT(std::string(row.where).size(), 5u) << CutPassName(row.pass);
    EXPECT_EQ(CaseOfEachPass().count(row.pass), 1u) << CutPassName(row.pass) << " has no case";
  }
  EXPECT_EQ(static_cast<int>(seen.size()), proto::CutOptions::Pass_descriptor()->value_count());
  EXPECT_EQ(CaseOfEachPass().size(), table.size());
  // In the order of the builder's steps.
  for (size_t k = 1; k < table.size(); ++k) EXPECT_LE(table[k - 1].step, table[k].step);
}

TEST(CutPassTableTest, ThePaperSkipsEveryPassInTheTablesOrder) {
  const proto::PipelineOptions paper = ReadOptionsFile(SourcePath("examples/options/paper.pbtxt"));
  const std::vector<CutPass>& table = CutPassTable();
  ASSERT_EQ(paper.cut().skip_passes_size(), static_cast<int>(table.size()));
  for (size_t k = 0; k < table.size(); ++k) {
    EXPECT_EQ(paper.cut().skip_passes(static_cast<int>(k)), table[k].pass);
    EXPECT_FALSE(RunsCutPass(paper.cut(), table[k].pass));
    EXPECT_TRUE(RunsCutPass(proto::CutOptions(), table[k].pass));
  }
  // The paper fixes W; a skipped pass turns its numbers off.
  EXPECT_GT(paper.cut().room_width_m(), 0);
  EXPECT_EQ(IslandMaxLengthM(paper.cut()), 0);
  EXPECT_EQ(WallGapMaxWidthM(paper.cut()), 0);
  EXPECT_EQ(MouthMaxWidthM(paper.cut()), 0);
  EXPECT_GT(IslandMaxLengthM(proto::CutOptions()), 0);
  EXPECT_GT(WallGapMaxWidthM(proto::CutOptions()), 0);
  // The paper's clean and match skip every pass of theirs too.
  EXPECT_EQ(paper.clean().skip_passes_size(),
            proto::CleanOptions::Pass_descriptor()->value_count());
  EXPECT_EQ(paper.match().skip_passes_size(),
            proto::MatchOptions::Pass_descriptor()->value_count());
}

TEST(CutPassTableTest, OptionsOfAPassAreItsOwnMessage) {
  proto::CutOptions options;
  options.mutable_wall_gaps()->set_max_width_m(2);
  for (const CutPass& row : CutPassTable()) {
    if (row.options_of == nullptr) continue;
    const google::protobuf::Message* message = row.options_of(options);
    ASSERT_NE(message, nullptr);
    EXPECT_NE(message, &options);
    if (row.pass == proto::CutOptions::CLOSE_WALL_GAPS) {
      EXPECT_EQ(message, &options.wall_gaps());
    }
  }
}

// A 6 x 6 m room with a 3.5 x 1.2 m block (a row of desks) in its middle:
// 1.25 m beside each end of it, 2.4 m above and below.
floorplan::FloorPlan RoomWithABlock() {
  floorplan::FloorPlan plan(7, 7);
  floorplan::DrawRoom(plan, {0.5, 0.5, 6, 6});
  floorplan::DrawFurniture(plan, {1.75, 2.9, 3.5, 1.2});
  return plan;
}

// The room's Cut Graph with W = 2 m, wider than the gaps beside the block.
proto::CutGraph CutOfRoomWithABlock(bool skip_islands) {
  proto::PipelineOptions options;
  options.mutable_cut()->set_room_width_m(2.0);
  if (skip_islands)
    options.mutable_cut()->add_skip_passes(proto::CutOptions::FREE_STANDING_ISLANDS);
  return RunAreaStages(CleanedMapFromImage(RoomWithABlock().image()), options).cut;
}

TEST(FreeStandingIslandsTest, TheBlockDoesNotStopTheRoomDisk) {
  EXPECT_EQ(CutOfRoomWithABlock(false).room_shapes_size(), 1);
}

TEST(FreeStandingIslandsTest, WithoutThePassTheBlockSplitsTheRoom) {
  // The disk fits above and below the block but not past its ends.
  EXPECT_EQ(CutOfRoomWithABlock(true).room_shapes_size(), 2);
}

// A 2 m corridor with a 6 x 4 m bay above it, open along the bay's whole
// width (its side walls end on the line of the corridor's top wall). The
// estimated W (about 1.75 m) lets the room disk into both.
floorplan::FloorPlan CorridorWithBay() {
  floorplan::FloorPlan plan(16, 8);
  floorplan::DrawRoom(plan, {1, 5, 14, 2});
  floorplan::DrawRoom(plan, {5, 1, 6, 4});
  floorplan::DrawDoor(plan, 8, 5, 5.85, floorplan::WallDirection::kHorizontal);
  return plan;
}

// The Cut Graph of the corridor with its bay, mouths up to 10 m closed
// unless the pass is skipped.
proto::CutGraph CutOfCorridorWithBay(bool skip_close_mouths) {
  proto::PipelineOptions options;
  options.mutable_cut()->mutable_mouths()->set_max_width_m(10);
  if (skip_close_mouths) options.mutable_cut()->add_skip_passes(proto::CutOptions::CLOSE_MOUTHS);
  return RunAreaStages(CleanDrawnMap(CorridorWithBay().image()), options).cut;
}

int ClosedMouths(const proto::CutGraph& cut) {
  int closed = 0;
  for (const proto::Opening& opening : cut.openings()) {
    closed += opening.kind() == proto::Opening::MOUTH && opening.closed();
  }
  return closed;
}

TEST(CloseMouthsTest, TheRoomDiskStopsAtTheBaysMouth) {
  const proto::CutGraph cut = CutOfCorridorWithBay(false);
  EXPECT_EQ(ClosedMouths(cut), 1);
  // The bay's room and the corridor's, apart.
  EXPECT_EQ(cut.room_shapes_size(), 2);
}

TEST(CloseMouthsTest, WithoutThePassTheDiskFillsBayAndCorridorAsOneRoom) {
  const proto::CutGraph cut = CutOfCorridorWithBay(true);
  EXPECT_EQ(ClosedMouths(cut), 0);
  EXPECT_EQ(cut.room_shapes_size(), 1);
}

}  // namespace
}  // namespace areagraph::testing

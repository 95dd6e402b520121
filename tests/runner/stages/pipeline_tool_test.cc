// ag-prune, ag-cut, ag-merge and ag-pipeline run as a user would.
#include <gtest/gtest.h>

#include "tests/support/raw_sqlite.h"
#include "tests/support/test_support.h"
#include "tools/example_maps/floor_plan.h"

namespace areagraph::testing {
namespace {

using floorplan::DrawDoor;
using floorplan::DrawRoom;
using floorplan::FloorPlan;
using floorplan::WallDirection;

class AreaToolsTest : public ::testing::Test {
 protected:
  void SetUp() override {
    FloorPlan plan(9.5, 5);
    DrawRoom(plan, {0.5, 0.5, 4, 4});
    DrawRoom(plan, {4.5, 0.5, 4.5, 4});
    DrawDoor(plan, 4.5, 2.5, 0.9, WallDirection::kVertical);
    const std::string image = dir_.File("two_rooms.png");
    floorplan::WritePlanPng(plan, image);
    const CommandResult import = RunTool("ag-import", {"--store", store_, image});
    ASSERT_EQ(import.exit_code, 0) << import.err;
  }

  CommandResult Run(const std::string& tool, std::vector<std::string> extra = {}) {
    std::vector<std::string> args{"--store", store_, "--map", "two_rooms"};
    args.insert(args.end(), extra.begin(), extra.end());
    return RunTool(tool, args);
  }

  // Exit 2 is bad usage (a bad option), 1 everything else (RunCommand).
  static void ExpectOneLineError(const CommandResult& result, const std::string& needle,
                                 int exit_code = 1) {
    EXPECT_EQ(result.exit_code, exit_code) << result.err;
    EXPECT_EQ(CountLines(result.err), 1) << result.err;
    EXPECT_NE(result.err.find(needle), std::string::npos) << result.err;
  }

  TempDir dir_;
  std::string store_ = dir_.File("store.db");
};

TEST_F(AreaToolsTest, StagesNameTheStageToRunFirst) {
  ExpectOneLineError(Run("ag-prune"), "run ag-voronoi first");
  ExpectOneLineError(Run("ag-cut"), "run ag-prune first");
  ExpectOneLineError(Run("ag-merge"), "run ag-cut first");
  const CommandResult unknown = RunTool("ag-pipeline", {"--store", store_, "--map", "nowhere"});
  ExpectOneLineError(unknown,
                     "map 'nowhere', clean: the map is not in the store; run ag-import first");
}

TEST_F(AreaToolsTest, PipelineRunsEveryStageOnceThenHitsTheCache) {
  const CommandResult first = Run("ag-pipeline");
  ASSERT_EQ(first.exit_code, 0) << first.err;
  EXPECT_EQ(CountLines(first.out), 7) << first.out;
  for (const char* stage : {"clean", "voronoi", "prune", "cut", "merge", "match"}) {
    EXPECT_NE(first.out.find(std::string(stage) + " "), std::string::npos) << stage;
  }
  EXPECT_EQ(first.out.find("cached"), std::string::npos) << first.out;
  EXPECT_NE(first.out.find("2 areas, 1 passages"), std::string::npos) << first.out;

  const CommandResult second = Run("ag-pipeline");
  ASSERT_EQ(second.exit_code, 0) << second.err;
  EXPECT_EQ(second.out.find("computed"), std::string::npos) << second.out;

  // The stage tools share the pipeline's cache.
  for (const char* tool : {"ag-prune", "ag-cut", "ag-merge", "ag-match"}) {
    const CommandResult stage = Run(tool);
    ASSERT_EQ(stage.exit_code, 0) << stage.err;
    EXPECT_EQ(CountLines(stage.out), 1) << stage.out;
    EXPECT_NE(stage.out.find("(cached)"), std::string::npos) << stage.out;
  }
}

TEST_F(AreaToolsTest, ChangingCutOptionsRerunsCutAndMergeOnly) {
  ASSERT_EQ(Run("ag-pipeline").exit_code, 0);
  const CommandResult rerun = Run("ag-pipeline", {"--set", "cut.room_width_m=1.0"});
  ASSERT_EQ(rerun.exit_code, 0) << rerun.err;
  for (const char* cached : {"clean   cached", "voronoi cached", "prune   cached"}) {
    EXPECT_NE(rerun.out.find(cached), std::string::npos) << rerun.out;
  }
  for (const char* computed : {"cut     computed", "merge   computed", "match   computed"}) {
    EXPECT_NE(rerun.out.find(computed), std::string::npos) << rerun.out;
  }
  const CommandResult cut = Run("ag-cut", {"--set", "cut.room_width_m=1.0"});
  ASSERT_EQ(cut.exit_code, 0) << cut.err;
  EXPECT_NE(cut.out.find("W = 1.00 m"), std::string::npos) << cut.out;
  EXPECT_NE(cut.out.find("(cached)"), std::string::npos) << cut.out;
}

// ag-pipeline hands each artifact to the next stage in memory; the stage
// tools read it back from the store. Both must write the same bytes.
TEST_F(AreaToolsTest, PipelineInOneProcessWritesWhatTheStageToolsWrite) {
  const std::string one_by_one = dir_.File("one_by_one.db");
  ASSERT_EQ(RunTool("ag-import", {"--store", one_by_one, dir_.File("two_rooms.png")}).exit_code, 0);
  const std::vector<std::string> tools = {"ag-clean", "ag-voronoi", "ag-prune",
                                          "ag-cut",   "ag-merge",   "ag-match"};
  for (const std::string& tool : tools) {
    const CommandResult stage = RunTool(tool, {"--store", one_by_one, "--map", "two_rooms"});
    ASSERT_EQ(stage.exit_code, 0) << tool << ": " << stage.err;
  }
  ASSERT_EQ(Run("ag-pipeline").exit_code, 0);
  const std::vector<std::string> digests = HeadDigests(store_);
  EXPECT_EQ(digests.size(), tools.size() + 1);  // and the import
  EXPECT_EQ(digests, HeadDigests(one_by_one));
}

TEST_F(AreaToolsTest, BadOptionsGiveOneLine) {
  ASSERT_EQ(Run("ag-pipeline").exit_code, 0);
  ExpectOneLineError(Run("ag-merge", {"--set", "merge.min_area_m2=-1"}), "merge.min_area_m2", 2);
  ExpectOneLineError(
      Run("ag-merge", {"--set", "merge.outline_tolerance_m=-0.1"}),
      "'merge.outline_tolerance_m' must be a number of metres in [0, 10000], got -0.1", 2);
  ExpectOneLineError(Run("ag-merge", {"--set", "merge.min_hole_m2=nan"}), "merge.min_hole_m2", 2);
  ExpectOneLineError(Run("ag-cut", {"--set", "cut.door_width_m=0.9"}), "set both or neither", 2);
  ExpectOneLineError(Run("ag-prune", {"--set", "prune.min_clearance_m=-0.5"}),
                     "prune.min_clearance_m", 2);
  // A width checked against the map fails while the stage runs: exit 1.
  ExpectOneLineError(Run("ag-pipeline", {"--set", "cut.room_width_m=5000"}), "wider than the map");
  // 10000 m was taken and turned rooms into slivers: bounded by the map's W.
  ExpectOneLineError(Run("ag-merge", {"--set", "merge.outline_tolerance_m=10000"}),
                     "merge.outline_tolerance_m = 10000 m is not below half the room width W = ");
  EXPECT_EQ(Run("ag-merge", {"--set", "merge.outline_tolerance_m=0.2"}).exit_code, 0);
}

}  // namespace
}  // namespace areagraph::testing

// ag-inspect --history and --diff as a user runs them: ag-run on a map file,
// the file changed (a wall taken out), ag-run again.
#include <gtest/gtest.h>

#include <filesystem>
#include <regex>
#include <sstream>
#include <string>

#include "tests/support/test_support.h"
#include "tools/example_maps/floor_plan.h"

namespace areagraph::testing {
namespace {

using namespace floorplan;

// Two rooms joined by a door (version 1), or one room where they were.
void WriteHouse(const std::string& path, bool wall) {
  FloorPlan plan(15, 8);
  if (wall) {
    DrawRoom(plan, {1, 1, 8, 6});
    DrawRoom(plan, {9, 1, 4, 6});
    DrawDoor(plan, 9, 4, 0.9, WallDirection::kVertical);
  } else {
    DrawRoom(plan, {1, 1, 12, 6});
  }
  WritePlanPng(plan, path);
}

class HistoryCliTest : public ::testing::Test {
 protected:
  void SetUp() override {
    std::filesystem::create_directory(dir_.File("maps"));
    WriteHouse(dir_.File("maps/house.png"), true);
    ASSERT_EQ(
        RunTool("ag-run", {"--store", store_, "--set", "cut.room_width_m=1.25", maps()}).exit_code,
        0);
    WriteHouse(dir_.File("maps/house.png"), false);
    ASSERT_EQ(
        RunTool("ag-run", {"--store", store_, "--set", "cut.room_width_m=1.25", maps()}).exit_code,
        0);
  }
  std::string maps() const { return dir_.File("maps"); }
  CommandResult Inspect(std::vector<std::string> args) {
    args.insert(args.begin(), {"--store", store_});
    return RunTool("ag-inspect", args);
  }

  TempDir dir_;
  const std::string store_ = dir_.File("s.db");
};

TEST_F(HistoryCliTest, HistoryListsEachVersionWithItsPredecessor) {
  const CommandResult history = Inspect({"--history", "house"});
  ASSERT_EQ(history.exit_code, 0) << history.err;
  const std::regex row(" +(\\d) +([0-9a-f]{12}) +\\S+Z +(-|[0-9a-f]{12}) +(\\d+) areas, .*");
  std::smatch first, second;
  const std::vector<std::string> lines = [&] {
    std::vector<std::string> out;
    std::istringstream in(history.out);
    for (std::string line; std::getline(in, line);) out.push_back(line);
    return out;
  }();
  ASSERT_EQ(lines.size(), 3u) << history.out;
  EXPECT_EQ(lines[0].find("version"), 0u) << lines[0];
  ASSERT_TRUE(std::regex_match(lines[1], first, row)) << lines[1];
  ASSERT_TRUE(std::regex_match(lines[2], second, row)) << lines[2];
  EXPECT_EQ(first[1].str(), "1");
  EXPECT_EQ(first[3].str(), "-");
  EXPECT_EQ(first[4].str(), "2");
  EXPECT_EQ(second[1].str(), "2");
  EXPECT_EQ(second[3].str(), first[2].str());
  EXPECT_EQ(second[4].str(), "1");
  EXPECT_NE(lines[2].find("(head)"), std::string::npos);
}

TEST_F(HistoryCliTest, DiffSaysTheWallIsGoneAndWhichIdSurvived) {
  const CommandResult diff = Inspect({"--map", "house", "--diff", "1", "head"});
  ASSERT_EQ(diff.exit_code, 0) << diff.err;
  // The 8 m room (id 0, drawn first) took in the 4 m one (id 1).
  EXPECT_NE(diff.out.find("version 1 -> 2: areas 0 added, 1 removed, 1 changed, 0 unchanged"),
            std::string::npos)
      << diff.out;
  EXPECT_NE(diff.out.find("  - area 1 (into area 0)\n"), std::string::npos) << diff.out;
  EXPECT_NE(diff.out.find("  ~ area 0: took in 1, grown"), std::string::npos) << diff.out;
  EXPECT_NE(diff.out.find("  - passage 0\n"), std::string::npos) << diff.out;

  const CommandResult json = Inspect({"--map", "house", "--diff", "1", "2", "--json"});
  ASSERT_EQ(json.exit_code, 0) << json.err;
  EXPECT_NE(json.out.find("\"removed_areas\": [\n  1\n ]"), std::string::npos) << json.out;
  EXPECT_NE(json.out.find("\"merged_from\": [\n    1\n   ]"), std::string::npos) << json.out;
  EXPECT_NE(json.out.find("\"map_name\": \"house\""), std::string::npos) << json.out;

  // The newest graph carries its stable ids and version into the exports:
  // the protobuf JSON as fields, the node-link JSON as attributes.
  const std::string message = dir_.File("house.pb.json"), node_link = dir_.File("house.json");
  ASSERT_EQ(RunTool("ag-export", {"--store", store_, "--map", "house", "--format", "protojson",
                                  "--out", message})
                .exit_code,
            0);
  EXPECT_NE(ReadFile(message).find("\"stable_id\""), std::string::npos);
  EXPECT_NE(ReadFile(message).find("\"number\": \"2\""), std::string::npos);
  ASSERT_EQ(RunTool("ag-export",
                    {"--store", store_, "--map", "house", "--format", "json", "--out", node_link})
                .exit_code,
            0);
  const std::string nodes = ReadFile(node_link);
  EXPECT_NE(nodes.find("\"graph\":{\"name\":\"house\",\"ids\":\"stable\",\"version\":2,"),
            std::string::npos)
      << nodes;
  EXPECT_NE(nodes.find("{\"id\":0,\"stable_id\":0,\"index\":0,\"name\":\"area_0\""),
            std::string::npos)
      << nodes;
  const std::string geojson = dir_.File("house.geojson");
  ASSERT_EQ(RunTool("ag-export",
                    {"--store", store_, "--map", "house", "--format", "geojson", "--out", geojson})
                .exit_code,
            0);
  EXPECT_NE(ReadFile(geojson).find("\"layer\":\"area\",\"area_id\":0,\"stable_id\":0,"),
            std::string::npos)
      << ReadFile(geojson);
}

TEST_F(HistoryCliTest, GcKeepsTheHistoryButNotTheOldGraph) {
  ASSERT_EQ(RunTool("ag-store", {"gc", "--store", store_}).exit_code, 0);
  const CommandResult history = Inspect({"--history", "house"});
  ASSERT_EQ(history.exit_code, 0) << history.err;
  EXPECT_NE(history.out.find("(no longer stored)"), std::string::npos) << history.out;
  const CommandResult diff = Inspect({"--map", "house", "--diff", "1", "2"});
  EXPECT_EQ(diff.exit_code, 1);
  EXPECT_NE(diff.err.find("version 1 of map 'house' is no longer stored"), std::string::npos)
      << diff.err;
}

TEST_F(HistoryCliTest, BadRequestsGiveOneLine) {
  const auto expect_error = [&](const std::vector<std::string>& args, const std::string& needle) {
    const CommandResult result = Inspect(args);
    EXPECT_NE(result.exit_code, 0) << result.out;
    EXPECT_EQ(CountLines(result.err), 1) << result.err;
    EXPECT_NE(result.err.find(needle), std::string::npos) << result.err;
  };
  expect_error({"--diff", "1", "2"}, "--diff needs --map");
  expect_error({"--map", "house", "--diff", "1", "7"}, "map 'house' has no version '7'");
  expect_error({"--map", "house", "--diff", "1"}, "--diff");
  expect_error({"--history", "nowhere"}, "map 'nowhere' is not in the store");
  expect_error({"--history", "house", "--map", "house"}, "--history lists one map's versions");
}

// NaN passed the range checks: every comparison with it is false.
TEST_F(HistoryCliTest, NotANumberIsNoThreshold) {
  for (const char* flag : {"--size-threshold", "--move-threshold"}) {
    for (const char* value : {"nan", "NaN", "-nan"}) {
      const CommandResult result = Inspect({"--map", "house", "--diff", "1", "2", flag, value});
      EXPECT_EQ(result.exit_code, 2) << flag << " " << value << ": " << result.out;
      EXPECT_EQ(CountLines(result.err), 1) << result.err;
      EXPECT_NE(result.err.find(std::string(flag) + ": must be a finite number, got " + value),
                std::string::npos)
          << result.err;
    }
  }
}

}  // namespace
}  // namespace areagraph::testing

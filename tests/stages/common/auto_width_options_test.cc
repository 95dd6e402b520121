// `auto` for cut.room_width_m: --set, options files, cache keys, and the
// tools that show the estimate.
#include <gtest/gtest.h>

#include <regex>

#include "common/error.h"
#include "stages/common/pipeline_options.h"
#include "tests/support/test_support.h"
#include "tools/example_maps/floor_plan.h"

namespace areagraph::testing {
namespace {

using floorplan::DrawDoor;
using floorplan::DrawRoom;
using floorplan::FloorPlan;
using floorplan::WallDirection;

TEST(AutoWidthOptionsTest, AutoIsZeroAndANumberFixesW) {
  proto::PipelineOptions options;
  EXPECT_EQ(options.cut().room_width_m(), 0);  // estimated by default
  ApplyOverride("cut.room_width_m=1.1", &options);
  EXPECT_DOUBLE_EQ(options.cut().room_width_m(), 1.1);
  ApplyOverride("cut.room_width_m=auto", &options);
  EXPECT_TRUE(options.cut().has_room_width_m());
  EXPECT_EQ(options.cut().room_width_m(), 0);
}

TEST(AutoWidthOptionsTest, AutoIsOnlyAWordForRoomWidth) {
  proto::PipelineOptions options;
  try {
    ApplyOverride("cut.room_width_m=automatic", &options);
    FAIL() << "no throw";
  } catch (const OptionsError& e) {
    EXPECT_NE(std::string(e.what()).find("double or auto"), std::string::npos) << e.what();
  }
  EXPECT_THROW(ApplyOverride("prune.min_clearance_m=auto", &options), OptionsError);
}

TEST(AutoWidthOptionsTest, AutoAndANumberHaveDifferentCanonicalBytes) {
  proto::PipelineOptions automatic, number;
  ApplyOverride("cut.room_width_m=auto", &automatic);
  ApplyOverride("cut.room_width_m=1.25", &number);
  EXPECT_NE(CanonicalBytes(automatic.cut()), CanonicalBytes(number.cut()));
  EXPECT_NE(CanonicalText(automatic.cut()).find("room_width_m: 0"), std::string::npos);
  // `auto` is the default.
  EXPECT_EQ(CanonicalBytes(automatic.cut()), CanonicalBytes(proto::CutOptions()));
}

TEST(AutoWidthOptionsTest, OptionsFilesTakeAutoAndNumbers) {
  TempDir dir;
  WriteFile(dir.File("auto.pbtxt"), "cut { room_width_m: auto }\n");
  const proto::PipelineOptions automatic = ReadOptionsFile(dir.File("auto.pbtxt"));
  EXPECT_TRUE(automatic.cut().has_room_width_m());
  EXPECT_EQ(automatic.cut().room_width_m(), 0);
  WriteFile(dir.File("number.pbtxt"), "cut { room_width_m: 0.95 }\n");
  EXPECT_DOUBLE_EQ(ReadOptionsFile(dir.File("number.pbtxt")).cut().room_width_m(), 0.95);
  // The switch it replaced is refused by name (protobuf's parser would skip
  // it without a word).
  WriteFile(dir.File("flag.pbtxt"), "cut { room_width_auto: true }\n");
  const std::string error = ErrorOf<OptionsError>([&] { ReadOptionsFile(dir.File("flag.pbtxt")); });
  EXPECT_NE(error.find("room_width_auto"), std::string::npos) << error;
}

// The cache key that ag-cut printed ("key 0123456789ab").
std::string CutKey(const CommandResult& result) {
  std::smatch match;
  const bool found = std::regex_search(result.out, match, std::regex("key ([0-9a-f]{12})"));
  return found ? match[1].str() : "";
}

TEST(AutoWidthToolsTest, CutAcceptsAutoStoresTheEstimateAndShowsIt) {
  TempDir dir;
  FloorPlan plan(12, 7.5);
  for (int i = 0; i < 3; ++i) DrawRoom(plan, {0.5 + i * 3.5, 0.5, 3.5, 4.5});
  DrawRoom(plan, {0.5, 5.0, 11, 2.0});
  for (int i = 0; i < 3; ++i) DrawDoor(plan, 2.25 + i * 3.5, 5.0, 0.9, WallDirection::kHorizontal);
  const std::string image = dir.File("rooms.png"), store = dir.File("store.db");
  floorplan::WritePlanPng(plan, image);
  ASSERT_EQ(RunTool("ag-import", {"--store", store, image}).exit_code, 0);
  const std::vector<std::string> map{"--store", store, "--map", "rooms"};
  auto run = [&](const std::string& tool, std::vector<std::string> extra) {
    std::vector<std::string> args = map;
    args.insert(args.end(), extra.begin(), extra.end());
    return RunTool(tool, args);
  };
  ASSERT_EQ(run("ag-pipeline", {"--set", "cut.room_width_m=1.25"}).exit_code, 0);
  const CommandResult fixed = run("ag-cut", {"--set", "cut.room_width_m=1.25"});
  const CommandResult automatic = run("ag-cut", {"--set", "cut.room_width_m=auto"});
  ASSERT_EQ(fixed.exit_code, 0) << fixed.err;
  ASSERT_EQ(automatic.exit_code, 0) << automatic.err;
  EXPECT_NE(automatic.out.find("(auto)"), std::string::npos) << automatic.out;
  EXPECT_NE(CutKey(fixed), "");
  EXPECT_NE(CutKey(automatic), "");
  EXPECT_NE(CutKey(fixed), CutKey(automatic));

  const CommandResult summary = run("ag-inspect", {"--stage", "cut"});
  ASSERT_EQ(summary.exit_code, 0) << summary.err;
  EXPECT_NE(summary.out.find("room width W: 1.0"), std::string::npos) << summary.out;
  EXPECT_NE(summary.out.find("widest door: 0.9"), std::string::npos) << summary.out;
  EXPECT_EQ(std::count(summary.out.begin(), summary.out.end(), '\n') > 0, true);
  EXPECT_NE(summary.out.find("  door 0.9"), std::string::npos) << summary.out;

  const CommandResult picture =
      run("ag-render", {"--stage", "cut", "--doors", "--out", dir.File("doors.png")});
  ASSERT_EQ(picture.exit_code, 0) << picture.err;
  EXPECT_GT(ReadFile(dir.File("doors.png")).size(), 1000u);
}

}  // namespace
}  // namespace areagraph::testing

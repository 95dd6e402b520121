// ag-render on a drawn map: whole pictures and zoomed windows.
#include <gtest/gtest.h>

#include <filesystem>
#include <opencv2/imgcodecs.hpp>

#include "tests/support/test_support.h"
#include "tools/example_maps/floor_plan.h"

namespace areagraph::testing {
namespace {

class AgRenderCli : public ::testing::Test {
 protected:
  void SetUp() override {
    floorplan::FloorPlan plan(6, 5);
    floorplan::DrawRoom(plan, {0.5, 0.5, 5, 4});
    const std::string image = dir_.File("room.png");
    floorplan::WritePlanPng(plan, image);
    ASSERT_EQ(RunTool("ag-import", {"--store", store_, image}).exit_code, 0);
    ASSERT_EQ(RunTool("ag-pipeline", {"--store", store_, "--map", "room"}).exit_code, 0);
  }

  CommandResult Render(std::vector<std::string> extra) {
    std::vector<std::string> args{"--store", store_, "--map", "room", "--out", out_};
    args.insert(args.end(), extra.begin(), extra.end());
    return RunTool("ag-render", args);
  }

  TempDir dir_;
  const std::string store_ = dir_.File("store.db");
  const std::string out_ = dir_.File("picture.png");
};

TEST_F(AgRenderCli, CropDrawsTheWindowAtTheScale) {
  const CommandResult whole = Render({"--scale", "2"});
  ASSERT_EQ(whole.exit_code, 0) << whole.err;
  const cv::Mat full = cv::imread(out_);
  EXPECT_EQ(full.cols, 2 * 120);
  EXPECT_EQ(full.rows, 2 * 100);
  const CommandResult zoomed = Render({"--scale", "8", "--crop", "10,5,30,20"});
  ASSERT_EQ(zoomed.exit_code, 0) << zoomed.err;
  const cv::Mat window = cv::imread(out_);
  EXPECT_EQ(window.cols, 8 * 30);
  EXPECT_EQ(window.rows, 8 * 20);
}

TEST_F(AgRenderCli, BadCropIsOneLineAndNonZero) {
  for (const char* crop : {"10,5,30", "1,2,-3,4", "500,500,10,10"}) {
    const CommandResult result = Render({"--scale", "2", "--crop", crop});
    EXPECT_EQ(result.exit_code, 1) << crop;
    EXPECT_EQ(CountLines(result.err), 1) << result.err;
    EXPECT_NE(result.err.find("ag-render: --crop"), std::string::npos) << result.err;
  }
}

// 0 used to be taken silently as "the default"; every value outside 1..16 is a usage error.
TEST_F(AgRenderCli, ScaleOutsideOneToSixteenIsAUsageError) {
  for (const char* scale : {"0", "-1", "17"}) {
    const CommandResult result = Render({"--scale", scale});
    EXPECT_EQ(result.exit_code, 2) << scale;
    EXPECT_EQ(CountLines(result.err), 1) << result.err;
    EXPECT_NE(result.err.find("--scale"), std::string::npos) << result.err;
  }
}

// The issue's --scale 16 on a 4000-px map asked for 12.3 GB and died under
// a memory limit with OpenCV's dump: the picture's size is checked first.
TEST(AgRenderLimitCli, PictureOverTheImportBoundIsRefusedUpFront) {
  TempDir dir;
  floorplan::FloorPlan plan(35, 35);  // 700 x 700 cells
  floorplan::DrawRoom(plan, {0.5, 0.5, 34, 34});
  const std::string image = dir.File("hall.png"), store = dir.File("s.db");
  floorplan::WritePlanPng(plan, image);
  ASSERT_EQ(RunTool("ag-import", {"--store", store, image}).exit_code, 0);
  ASSERT_EQ(RunTool("ag-clean", {"--store", store, "--map", "hall"}).exit_code, 0);
  const std::string out = dir.File("hall_x16.png");
  for (const char* stage : {"import", "clean"}) {
    const CommandResult result = RunTool("ag-render", {"--store", store, "--map", "hall", "--stage",
                                                       stage, "--scale", "16", "--out", out});
    EXPECT_EQ(result.exit_code, 1) << stage;
    EXPECT_EQ(result.err,
              "ag-render: --scale 16 would draw the 700 x 700 map as 1.2544e+08 pixels, more "
              "than 1e+08; use --scale 14 or less\n")
        << stage;
    EXPECT_FALSE(std::filesystem::exists(out)) << stage;
  }
  EXPECT_EQ(RunTool("ag-render", {"--store", store, "--map", "hall", "--stage", "import", "--scale",
                                  "2", "--out", out})
                .exit_code,
            0);
}

}  // namespace
}  // namespace areagraph::testing

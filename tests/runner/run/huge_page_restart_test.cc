// Programs that restart with glibc's huge-page tunable for a big map
// (stages/common/huge_page_restart.h) end as they would without it: ag-run
// before it touches the store, a stage executable after reading the map's
// source from it.
#include <gtest/gtest.h>

#include <fstream>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "tests/runner/run/runner_test_support.h"

namespace areagraph {
namespace {

using testing::CommandResult;
using testing::RunTool;
using testing::TempDir;

// A big map that cannot be decoded fails as it would without the restart,
// once, with the store holding its failure.
TEST(HugePageRestartRunTest, ARestartedRunEndsAsAnyOther) {
  const TempDir dir;
  std::ofstream(dir.File("big.png"), std::ios::binary) << testing::PngHeaderBytes(3000, 3000);
  CommandResult result;
  const proto::RunSummary summary =
      testing::RunJson({"--store", dir.File("s.db"), "--jobs", "1", dir.File("big.png")}, &result);
  EXPECT_EQ(result.exit_code, 1) << result.err;
  EXPECT_EQ(summary.maps(), 1);
  EXPECT_EQ(summary.failed(), 1);
  const CommandResult failures = RunTool("ag-inspect", {"--store", dir.File("s.db"), "--failures"});
  EXPECT_EQ(failures.exit_code, 0) << failures.err;
  EXPECT_NE(failures.out.find("big"), std::string::npos) << failures.out;
}

// 6 Mpx, one room: ag-clean and ag-pipeline restart (their store's map row
// names a PNG over 5 Mpx) and compute as they would without.
TEST(HugePageRestartRunTest, StageExecutablesOnABigMapComputeAfterTheRestart) {
  const TempDir dir;
  cv::Mat image(2000, 3000, CV_8UC1, cv::Scalar(205));
  cv::rectangle(image, cv::Rect(100, 100, 600, 400), cv::Scalar(254), cv::FILLED);
  cv::rectangle(image, cv::Rect(100, 100, 600, 400), cv::Scalar(0), 3);
  ASSERT_TRUE(cv::imwrite(dir.File("room.png"), image));
  const std::string store = dir.File("s.db");
  const CommandResult import =
      RunTool("ag-import", {"--store", store, "--map", "room", dir.File("room.png")});
  ASSERT_EQ(import.exit_code, 0) << import.err;
  const CommandResult clean = RunTool("ag-clean", {"--store", store, "--map", "room"});
  ASSERT_EQ(clean.exit_code, 0) << clean.err;
  EXPECT_NE(clean.out.find("(computed)"), std::string::npos) << clean.out;
  EXPECT_EQ(clean.err, "");
  const CommandResult pipeline = RunTool("ag-pipeline", {"--store", store, "--map", "room"});
  ASSERT_EQ(pipeline.exit_code, 0) << pipeline.err;
  EXPECT_NE(pipeline.out.find("clean   cached"), std::string::npos) << pipeline.out;
  EXPECT_NE(pipeline.out.find("merge   computed"), std::string::npos) << pipeline.out;
}

}  // namespace
}  // namespace areagraph

// Programs that restart with glibc's huge-page tunable for a big map
// (common/process_setup/huge_page_restart.h) do so once, say so in their report,
// and end as they would without it: ag-run before it touches the store, a
// stage executable and ag-pipeline after reading the map's source from it.
// Small maps do not restart.
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

// One room on a grey field of `width` x `height` pixels, as <dir>/<name>.png.
std::string WriteRoomMap(const TempDir& dir, const std::string& name, int width, int height) {
  cv::Mat image(height, width, CV_8UC1, cv::Scalar(205));
  cv::rectangle(image, cv::Rect(100, 100, 600, 400), cv::Scalar(254), cv::FILLED);
  cv::rectangle(image, cv::Rect(100, 100, 600, 400), cv::Scalar(0), 3);
  const std::string path = dir.File(name + ".png");
  EXPECT_TRUE(cv::imwrite(path, image));
  return path;
}

// 6 Mpx: over kHugePageRestartPixels.
std::string WriteBigRoom(const TempDir& dir) { return WriteRoomMap(dir, "room", 3000, 2000); }

int Restarts(const CommandResult& result, const std::string& tool) {
  return testing::CountOccurrences(result.out, tool + ": restarted with glibc.malloc.hugetlb=1\n");
}

TEST(HugePageRestartRunTest, ARunRestartsOnceForABigMapAndNotForASmallOne) {
  const TempDir dir;
  CommandResult result;
  const proto::RunSummary big =
      testing::RunJson({"--store", dir.File("s.db"), "--jobs", "1", WriteBigRoom(dir)}, &result);
  EXPECT_EQ(result.exit_code, 0) << result.err;
  EXPECT_EQ(big.succeeded(), 1);
  EXPECT_TRUE(big.huge_page_restart()) << result.out;
  const proto::RunSummary small = testing::RunJson(
      {"--store", dir.File("s.db"), "--jobs", "1", WriteRoomMap(dir, "small", 800, 600)}, &result);
  EXPECT_EQ(small.succeeded(), 1) << result.err;
  EXPECT_FALSE(small.huge_page_restart()) << result.out;
  // The text summary says it once; the big map is all cache hits now.
  const CommandResult text = RunTool("ag-run", {"--store", dir.File("s.db"), dir.File("room.png")});
  EXPECT_EQ(text.exit_code, 0) << text.err;
  EXPECT_EQ(testing::CountOccurrences(text.out, "restarted with glibc.malloc.hugetlb=1"), 1)
      << text.out;
}

// ag-clean and ag-pipeline restart (their store's map row names a
// PNG over 5 Mpx), once each, and compute as they would without.
TEST(HugePageRestartRunTest, StageExecutablesOnABigMapComputeAfterTheRestart) {
  const TempDir dir;
  const std::string store = dir.File("s.db");
  const CommandResult import =
      RunTool("ag-import", {"--store", store, "--map", "room", WriteBigRoom(dir)});
  ASSERT_EQ(import.exit_code, 0) << import.err;
  EXPECT_EQ(Restarts(import, "ag-import"), 0) << import.out;
  const CommandResult clean = RunTool("ag-clean", {"--store", store, "--map", "room"});
  ASSERT_EQ(clean.exit_code, 0) << clean.err;
  EXPECT_NE(clean.out.find("(computed)"), std::string::npos) << clean.out;
  EXPECT_EQ(Restarts(clean, "ag-clean"), 1) << clean.out;
  EXPECT_EQ(clean.err, "");
  const CommandResult pipeline = RunTool("ag-pipeline", {"--store", store, "--map", "room"});
  ASSERT_EQ(pipeline.exit_code, 0) << pipeline.err;
  EXPECT_NE(pipeline.out.find("clean   cached"), std::string::npos) << pipeline.out;
  EXPECT_NE(pipeline.out.find("merge   computed"), std::string::npos) << pipeline.out;
  EXPECT_EQ(Restarts(pipeline, "ag-pipeline"), 1) << pipeline.out;
}

TEST(HugePageRestartRunTest, StageExecutablesOnASmallMapDoNotRestart) {
  const TempDir dir;
  const std::string store = dir.File("s.db");
  const CommandResult import = RunTool(
      "ag-import", {"--store", store, "--map", "room", WriteRoomMap(dir, "room", 800, 600)});
  ASSERT_EQ(import.exit_code, 0) << import.err;
  const CommandResult clean = RunTool("ag-clean", {"--store", store, "--map", "room"});
  ASSERT_EQ(clean.exit_code, 0) << clean.err;
  EXPECT_EQ(Restarts(clean, "ag-clean"), 0) << clean.out;
}

}  // namespace
}  // namespace areagraph

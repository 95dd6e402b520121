// The thread policy of ag-run's workers: each gets a share of the cores for
// OpenCV's pool, or what --threads-per-map asks for.
#include "runner/run/worker_threads.h"

#include <gtest/gtest.h>

#include <CLI/CLI.hpp>
#include <map>
#include <opencv2/core/utility.hpp>
#include <string>
#include <vector>

#include "common/error.h"
#include "runner/run/process_pool.h"
#include "runner/run/run_command_line.h"

namespace areagraph {
namespace {

TEST(WorkerThreadsTest, EachWorkerGetsAnEqualShareOfTheCoresAtLeastOne) {
  EXPECT_EQ(ThreadsPerMap(0, 8, 2), 4);
  EXPECT_EQ(ThreadsPerMap(0, 8, 3), 2);  // rounded down: never more threads than cores
  EXPECT_EQ(ThreadsPerMap(0, 2, 1), 2);
  EXPECT_EQ(ThreadsPerMap(0, 2, 2), 1);
  EXPECT_EQ(ThreadsPerMap(0, 2, 8), 1);
  EXPECT_EQ(ThreadsPerMap(0, 0, 1), 1);  // hardware_concurrency may not know
  EXPECT_EQ(ThreadsPerMap(0, 4, 0), 4);
}

TEST(WorkerThreadsTest, AskedCountWins) {
  EXPECT_EQ(ThreadsPerMap(3, 2, 2), 3);
  EXPECT_EQ(ThreadsPerMap(1, 16, 1), 1);
}

// In forked workers, as ag-run's: each reports the pool size it set.
TEST(WorkerThreadsTest, ForkedWorkersRunWithTheirShare) {
  for (const auto& [threads, expected] : std::map<int, int>{{1, 1}, {2, 2}}) {
    std::map<int, std::string> seen;
    ProcessPool pool(
        2,
        [threads = threads](int, EventWriter& events) {
          UseThreadsPerMap(threads);
          events.Write(std::to_string(cv::getNumThreads()));
        },
        [&](int task, const std::string& message) { seen[task] = message; },
        [](int, const std::string& crash) { EXPECT_EQ(crash, ""); });
    pool.Run(3);
    ASSERT_EQ(seen.size(), 3u);
    for (const auto& [task, count] : seen) {
      EXPECT_EQ(count, std::to_string(expected)) << "threads " << threads << ", task " << task;
    }
  }
}

RunFlags Parse(std::vector<std::string> args) {
  CLI::App app;
  RunFlags flags;
  AddRunFlags(app, flags);
  args.push_back("map.png");
  std::vector<const char*> argv = {"ag-run"};
  for (const std::string& arg : args) argv.push_back(arg.c_str());
  app.parse(static_cast<int>(argv.size()), argv.data());
  CheckRunFlags(app, flags);
  return flags;
}

TEST(WorkerThreadsTest, ThreadsPerMapOption) {
  EXPECT_EQ(Parse({}).threads_per_map, 0);
  EXPECT_EQ(Parse({"--threads-per-map", "3"}).threads_per_map, 3);
  EXPECT_EQ(Parse({"--threads-per-map=1", "--jobs", "4"}).threads_per_map, 1);
  EXPECT_THROW(Parse({"--threads-per-map", "-1"}), OptionsError);
  EXPECT_THROW(Parse({"--threads-per-map", "2000"}), OptionsError);
  EXPECT_THROW(Parse({"--threads-per-map", "two"}), CLI::ParseError);

  CLI::App app;
  RunFlags flags;
  AddRunFlags(app, flags);
  EXPECT_NE(app.help().find("--threads-per-map"), std::string::npos);
}

}  // namespace
}  // namespace areagraph

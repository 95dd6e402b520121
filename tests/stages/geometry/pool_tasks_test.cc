// RunTasks (stages/geometry/pool_tasks.h): every task runs once, the first
// `on_caller` on the calling thread, and the first failing task's exception
// in list order reaches the caller.
#include "stages/geometry/pool_tasks.h"

#include <gtest/gtest.h>

#include <stdexcept>
#include <thread>

#include "tests/support/thread_count.h"

namespace areagraph {
namespace {

using testing::ThreadCount;

TEST(RunTasksTest, EveryTaskRunsOnceAndTheFirstOnesOnTheCaller) {
  for (const int threads : {1, 2}) {
    const ThreadCount thread_count(threads);
    constexpr int kTasks = 40;
    std::vector<int> runs(kTasks, 0);
    std::vector<std::thread::id> where(kTasks);
    std::vector<std::function<void()>> tasks;
    for (int t = 0; t < kTasks; ++t) {
      tasks.push_back([&, t] {
        ++runs[t];
        where[t] = std::this_thread::get_id();
        volatile double sink = 0;
        for (int i = 0; i < 20000; ++i) sink = sink + i;  // long enough to share
      });
    }
    RunTasks(tasks, /*on_caller=*/3);
    EXPECT_EQ(runs, std::vector<int>(kTasks, 1)) << threads << " threads";
    for (int t = 0; t < 3; ++t) EXPECT_EQ(where[t], std::this_thread::get_id()) << t;
  }
}

TEST(RunTasksTest, TheFirstFailingTasksExceptionInListOrderReachesTheCaller) {
  const ThreadCount thread_count(2);
  bool last_ran = false;
  try {
    RunTasks({[] {}, [] { throw std::runtime_error("second"); },
              [] { throw std::logic_error("third"); }, [&] { last_ran = true; }});
    FAIL() << "no exception";
  } catch (const std::runtime_error& error) {
    EXPECT_STREQ(error.what(), "second");
  }
  EXPECT_TRUE(last_ran);
}

}  // namespace
}  // namespace areagraph

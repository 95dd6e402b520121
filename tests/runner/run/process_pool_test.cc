// ProcessPool on its own: tasks in forked workers, framed messages, tasks
// that throw, workers that crash or quit, and every task ending exactly once.
#include "runner/run/process_pool.h"

#include <gtest/gtest.h>
#include <poll.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "tests/support/test_support.h"

namespace areagraph {
namespace {

// What the parent saw of each task, in order: its messages, then "end:" and
// the crash text of each time it ended.
struct PoolLog {
  std::map<int, std::vector<std::string>> calls;
  int ticks = 0;
};

PoolLog RunPool(int jobs, int tasks, ProcessPool::Work work,
                ProcessPool::OnWorkerEnd on_worker_end = nullptr) {
  PoolLog log;
  ProcessPool pool(
      jobs, std::move(work),
      [&](int task, const std::string& message) { log.calls[task].push_back(message); },
      [&](int task, const std::string& crash) { log.calls[task].push_back("end:" + crash); },
      [&] { ++log.ticks; }, std::move(on_worker_end));
  pool.Run(tasks);
  return log;
}

std::string PidMessage() { return "pid " + std::to_string(getpid()); }

// Work that reports the worker's pid and its task.
void ReportPid(int task, EventWriter& events) {
  events.Write(PidMessage());
  events.Write("task " + std::to_string(task));
}

// Every task in 0..tasks-1 ran and ended once without a crash, except those
// in `crashes`, which ended once with that text; nothing else was reported.
void ExpectEndings(const PoolLog& log, int tasks, const std::map<int, std::string>& crashes = {}) {
  EXPECT_EQ(log.calls.size(), static_cast<size_t>(tasks));
  for (int task = 0; task < tasks; ++task) {
    ASSERT_EQ(log.calls.count(task), 1u) << "task " << task << " never reported";
    const std::vector<std::string>& calls = log.calls.at(task);
    int ends = 0;
    for (const std::string& call : calls) ends += call.rfind("end:", 0) == 0 ? 1 : 0;
    EXPECT_EQ(ends, 1) << "task " << task;
    const auto crash = crashes.find(task);
    EXPECT_EQ(calls.back(), "end:" + (crash == crashes.end() ? "" : crash->second))
        << "task " << task;
  }
}

// The pid that task `task` reported first.
std::string PidOf(const PoolLog& log, int task) {
  const std::vector<std::string>& calls = log.calls.at(task);
  return calls.empty() || calls[0].rfind("pid ", 0) != 0 ? "none" : calls[0];
}

std::set<std::string> PidsOf(const PoolLog& log) {
  std::set<std::string> pids;
  for (const auto& [task, calls] : log.calls) pids.insert(PidOf(log, task));
  return pids;
}

// A segfault in a worker, without leaving a core file behind.
[[noreturn]] void Segfault() {
  const rlimit no_core{0, 0};
  setrlimit(RLIMIT_CORE, &no_core);
  std::raise(SIGSEGV);
  _exit(99);  // not reached
}

TEST(ProcessPoolTest, ZeroTasksReportNothing) {
  const PoolLog log = RunPool(4, 0, ReportPid);
  EXPECT_TRUE(log.calls.empty());
}

TEST(ProcessPoolTest, EachTaskEndsOnceAfterItsMessagesInOrder) {
  const PoolLog log = RunPool(3, 25, ReportPid);
  ExpectEndings(log, 25);
  for (int task = 0; task < 25; ++task) {
    const std::vector<std::string>& calls = log.calls.at(task);
    ASSERT_EQ(calls.size(), 3u);
    EXPECT_EQ(calls[1], "task " + std::to_string(task));
  }
}

TEST(ProcessPoolTest, TasksRunInJobsWorkersOtherThanTheParent) {
  const PoolLog log = RunPool(2, 10, ReportPid);
  ExpectEndings(log, 10);
  const std::set<std::string> pids = PidsOf(log);
  EXPECT_EQ(pids.size(), 2u);
  EXPECT_EQ(pids.count(PidMessage()), 0u);
  EXPECT_EQ(pids.count("none"), 0u);
}

TEST(ProcessPoolTest, MoreJobsThanTasksStartsOneWorkerPerTask) {
  const PoolLog log = RunPool(8, 3, ReportPid);
  ExpectEndings(log, 3);
  EXPECT_EQ(PidsOf(log).size(), 3u);
}

TEST(ProcessPoolTest, NoJobsMeansOneWorker) {
  for (const int jobs : {0, -3}) {
    const PoolLog log = RunPool(jobs, 4, ReportPid);
    ExpectEndings(log, 4);
    EXPECT_EQ(PidsOf(log).size(), 1u) << "jobs " << jobs;
  }
}

TEST(ProcessPoolTest, MessagesOfAnyBytesArriveWhole) {
  std::string binary("a\0b\xff\n\t", 6);
  std::string big(200000, ' ');  // bigger than a pipe's buffer and a read's chunk
  for (size_t i = 0; i < big.size(); ++i) big[i] = static_cast<char>(i * 7 % 256);
  std::vector<std::string> sent = {"", binary, big};
  for (int i = 0; i < 2000; ++i) sent.push_back(std::to_string(i));  // frames split across reads
  const PoolLog log = RunPool(2, 2, [&](int, EventWriter& events) {
    for (const std::string& message : sent) events.Write(message);
  });
  ExpectEndings(log, 2);
  for (int task = 0; task < 2; ++task) {
    std::vector<std::string> got = log.calls.at(task);
    got.pop_back();  // the end
    ASSERT_EQ(got.size(), sent.size());
    for (size_t i = 0; i < sent.size(); ++i) EXPECT_TRUE(got[i] == sent[i]) << "message " << i;
  }
}

TEST(ProcessPoolTest, TaskThatThrowsEndsWithWhatAndTheWorkerGoesOn) {
  const PoolLog log = RunPool(1, 4, [](int task, EventWriter& events) {
    ReportPid(task, events);
    if (task == 1) throw std::runtime_error("cannot read map 1");
  });
  ExpectEndings(log, 4, {{1, "cannot read map 1"}});
  EXPECT_EQ(log.calls.at(1).size(), 3u);  // its messages came before the end
  EXPECT_EQ(PidsOf(log).size(), 1u);      // a throw does not cost the worker
}

TEST(ProcessPoolTest, TaskThatThrowsANonStandardExceptionIsReportedToo) {
  const PoolLog log = RunPool(1, 3, [](int task, EventWriter& events) {
    ReportPid(task, events);
    if (task == 1) throw 42;
  });
  ExpectEndings(log, 3, {{1, "the task threw an exception that is not a std::exception"}});
  EXPECT_EQ(PidsOf(log).size(), 1u);
}

TEST(ProcessPoolTest, CrashedWorkerIsReportedAndReplaced) {
  const PoolLog log = RunPool(1, 4, [](int task, EventWriter& events) {
    ReportPid(task, events);
    if (task == 1) Segfault();
  });
  ExpectEndings(log, 4, {{1, "the worker process died of signal 11 (Segmentation fault)"}});
  // Messages written before the crash still arrive.
  EXPECT_EQ(log.calls.at(1).size(), 3u);
  EXPECT_EQ(PidOf(log, 1), PidOf(log, 0));
  EXPECT_NE(PidOf(log, 2), PidOf(log, 1));  // the replacement
  EXPECT_EQ(PidOf(log, 3), PidOf(log, 2));
}

TEST(ProcessPoolTest, WorkerThatExitsInsideATaskIsACrashEvenWithStatusZero) {
  const PoolLog log = RunPool(2, 6, [](int task, EventWriter& events) {
    ReportPid(task, events);
    if (task == 2) _exit(7);
    if (task == 4) _exit(0);
  });
  ExpectEndings(log, 6,
                {{2, "the worker process exited with status 7"},
                 {4, "the worker process exited with status 0"}});
  // A worker that died runs nothing more; both cannot have been the two
  // first workers and task 5's as well.
  for (int task = 3; task < 6; ++task) EXPECT_NE(PidOf(log, task), PidOf(log, 2)) << task;
  EXPECT_NE(PidOf(log, 5), PidOf(log, 4));
  EXPECT_GE(PidsOf(log).size(), 3u);
}

TEST(ProcessPoolTest, EveryTaskCrashingStillEndsEachOnce) {
  std::map<int, std::string> crashes;
  for (int task = 0; task < 5; ++task) crashes[task] = "the worker process exited with status 1";
  const PoolLog log = RunPool(2, 5, [](int task, EventWriter& events) {
    ReportPid(task, events);
    _exit(1);
  });
  ExpectEndings(log, 5, crashes);
  EXPECT_EQ(PidsOf(log).size(), 5u);
}

TEST(ProcessPoolTest, LastTasksCrashingEndsTheRun) {
  const PoolLog log = RunPool(3, 3, [](int task, EventWriter& events) {
    ReportPid(task, events);
    if (task > 0) Segfault();
  });
  const std::string segfault = "the worker process died of signal 11 (Segmentation fault)";
  ExpectEndings(log, 3, {{1, segfault}, {2, segfault}});
}

TEST(ProcessPoolTest, RunsAgainWithNewTasks) {
  PoolLog log;
  ProcessPool pool(
      2, ReportPid,
      [&](int task, const std::string& message) { log.calls[task].push_back(message); },
      [&](int task, const std::string& crash) { log.calls[task].push_back("end:" + crash); });
  pool.Run(3);
  ExpectEndings(log, 3);
  log.calls.clear();
  pool.Run(2);
  ExpectEndings(log, 2);
}

TEST(ProcessPoolTest, TicksWhileWorkersRun) {
  const PoolLog log = RunPool(1, 1, ReportPid);
  ExpectEndings(log, 1);
  EXPECT_GT(log.ticks, 0);
}

// Each worker's end hook, as lines of the file `log`: "end", or "last" and
// whether the workers that wrote before it were all gone by then.
void AppendWorkerEnd(const std::string& log, bool last) {
  std::string line = last ? "last" : "end";
  if (last) {
    std::ifstream earlier(log);
    std::string gone = " others gone";
    for (std::string other; std::getline(earlier, other);) {
      const pid_t pid = std::stoi(other.substr(other.rfind(' ') + 1));
      if (kill(pid, 0) == 0 || errno != ESRCH) gone = " others alive";
    }
    line += gone;
  }
  std::ofstream(log, std::ios::app) << line << " " << getpid() << "\n";
}

// The hook's lines without their pids.
std::vector<std::string> WorkerEnds(const std::string& log) {
  std::vector<std::string> ends;
  std::ifstream in(log);
  for (std::string line; std::getline(in, line);) ends.push_back(line.substr(0, line.rfind(' ')));
  return ends;
}

PoolLog RunPoolWithEndHook(const std::string& log, int jobs, int tasks, ProcessPool::Work work) {
  return RunPool(jobs, tasks, std::move(work), [&](bool last) { AppendWorkerEnd(log, last); });
}

const char kSegfaulted[] = "the worker process died of signal 11 (Segmentation fault)";

// Each worker's end hook writes to a file (AppendWorkerEnd).
class ProcessPoolEndTest : public ::testing::Test {
 protected:
  testing::TempDir dir_;
  const std::string log_ = dir_.File("ends");
};

TEST_F(ProcessPoolEndTest, EveryWorkerEndsOnceAndOneLastAfterTheOthersExited) {
  const PoolLog pool_log = RunPoolWithEndHook(log_, 3, 12, [](int task, EventWriter& events) {
    ReportPid(task, events);
    usleep(static_cast<useconds_t>(task % 4) * 3000);
  });
  ExpectEndings(pool_log, 12);
  EXPECT_EQ(WorkerEnds(log_), (std::vector<std::string>{"end", "end", "last others gone"}));
}

TEST_F(ProcessPoolEndTest, OneWorkerEndsAsTheLast) {
  ExpectEndings(RunPoolWithEndHook(log_, 1, 3, ReportPid), 3);
  EXPECT_EQ(WorkerEnds(log_), std::vector<std::string>{"last others gone"});
}

TEST_F(ProcessPoolEndTest, NoWorkerIsLastWhenTheLastTaskCrashesIt) {
  const PoolLog pool_log = RunPoolWithEndHook(log_, 2, 2, [this](int task, EventWriter& events) {
    ReportPid(task, events);
    if (task == 0) return;
    // Crashes only once the other worker has ended.
    for (int wait = 0; wait < 2000 && WorkerEnds(log_).empty(); ++wait) usleep(5000);
    Segfault();
  });
  ExpectEndings(pool_log, 2, {{1, kSegfaulted}});
  EXPECT_EQ(WorkerEnds(log_), std::vector<std::string>{"end"});
}

TEST_F(ProcessPoolEndTest, WorkerThatCrashedEarlierLeavesTheLastToItsReplacement) {
  const PoolLog pool_log = RunPoolWithEndHook(log_, 1, 4, [](int task, EventWriter& events) {
    ReportPid(task, events);
    if (task == 1) Segfault();
  });
  ExpectEndings(pool_log, 4, {{1, kSegfaulted}});
  EXPECT_EQ(WorkerEnds(log_), std::vector<std::string>{"last others gone"});
}

TEST(ProcessPoolTest, WhatTheEndHookThrowsIsDropped) {
  ExpectEndings(RunPool(2, 5, ReportPid, [](bool) { throw std::runtime_error("cannot fold"); }), 5);
}

TEST(ProcessPoolTest, WorkersDieWithTheParent) {
  int report[2];
  ASSERT_EQ(pipe(report), 0);
  const pid_t runner = fork();
  ASSERT_GE(runner, 0);
  if (runner == 0) {
    // A runner whose one worker reports its pid and then waits forever.
    close(report[0]);
    ProcessPool pool(
        1,
        [&](int, EventWriter&) {
          const pid_t pid = getpid();
          if (write(report[1], &pid, sizeof(pid)) != sizeof(pid)) _exit(5);
          while (true) pause();
        },
        [](int, const std::string&) {}, [](int, const std::string&) {});
    pool.Run(1);
    _exit(0);
  }
  close(report[1]);
  pid_t worker = -1;
  ASSERT_EQ(read(report[0], &worker, sizeof(worker)), static_cast<ssize_t>(sizeof(worker)));
  kill(runner, SIGKILL);
  int status = 0;
  waitpid(runner, &status, 0);
  // The report pipe reaches its end once the worker, its last writer, is gone.
  pollfd fd{report[0], POLLIN, 0};
  const bool ended = poll(&fd, 1, 5000) == 1 && read(report[0], &status, 1) == 0;
  EXPECT_TRUE(ended) << "worker " << worker << " outlived its runner";
  if (!ended) kill(worker, SIGKILL);
  close(report[0]);
}

}  // namespace
}  // namespace areagraph

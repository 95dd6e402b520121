#pragma once

#include <algorithm>
#include <atomic>
#include <exception>
#include <functional>
#include <thread>
#include <vector>

#include "stages/geometry/parallel_ranges.h"

namespace areagraph {

// Runs each of `tasks` once on OpenCV's pool: one worker per pool thread (at
// most one per task) takes the next task in list order until none is left,
// so put the longest first. The first `on_caller` tasks run on the calling
// thread, in order, before it takes others: a task that frees much of the
// caller's memory and allocates as much again (cut's edges) then allocates
// from the caller's malloc arena, which holds what it freed, and not from a
// pool thread's, which would add to the peak. Tasks that write only their
// own results give the same outputs whichever thread runs them. When tasks
// throw, the first one's exception in list order reaches the caller after
// all have run.
inline void RunTasks(const std::vector<std::function<void()>>& tasks, size_t on_caller = 0) {
  const int workers =
      std::max(1, std::min<int>(cv::getNumThreads(), static_cast<int>(tasks.size())));
  std::vector<std::exception_ptr> errors(tasks.size());
  auto run = [&](size_t task) {
    try {
      tasks[task]();
    } catch (...) {
      errors[task] = std::current_exception();
    }
  };
  std::atomic<size_t> next{on_caller};
  std::atomic<bool> caller_done{on_caller == 0};
  const std::thread::id caller = std::this_thread::get_id();
  auto run_on_caller = [&] {
    if (caller_done.exchange(true)) return;
    for (size_t task = 0; task < on_caller && task < tasks.size(); ++task) run(task);
  };
  ForEachRange(static_cast<size_t>(workers), workers, [&](size_t, size_t, int) {
    if (std::this_thread::get_id() == caller) run_on_caller();
    for (size_t task = next++; task < tasks.size(); task = next++) run(task);
  });
  run_on_caller();  // when no range ran on the calling thread
  for (const std::exception_ptr& error : errors) {
    if (error) std::rethrow_exception(error);
  }
}

}  // namespace areagraph

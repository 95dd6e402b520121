#pragma once

#include <algorithm>
#include <atomic>
#include <exception>
#include <functional>
#include <vector>

#include "stages/geometry/parallel_ranges.h"

namespace areagraph {

// Runs each of `tasks` once on OpenCV's pool: one worker per pool thread (at
// most one per task) takes the next task in list order until none is left,
// so put the longest first. Tasks that write only their own results give
// the same outputs whichever thread runs them. When tasks throw, the first
// one's exception in list order reaches the caller, after all have run (on
// one thread, the serial steps would have stopped at that one too).
inline void RunTasks(const std::vector<std::function<void()>>& tasks) {
  const int workers = std::min<int>(cv::getNumThreads(), static_cast<int>(tasks.size()));
  std::vector<std::exception_ptr> errors(tasks.size());
  std::atomic<size_t> next{0};
  ForEachRange(static_cast<size_t>(std::max(workers, 1)), std::max(workers, 1),
               [&](size_t, size_t, int) {
                 for (size_t task = next++; task < tasks.size(); task = next++) {
                   try {
                     tasks[task]();
                   } catch (...) {
                     errors[task] = std::current_exception();
                   }
                 }
               });
  for (const std::exception_ptr& error : errors) {
    if (error) std::rethrow_exception(error);
  }
}

}  // namespace areagraph

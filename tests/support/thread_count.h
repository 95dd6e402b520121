#pragma once

#include <opencv2/core/utility.hpp>

namespace areagraph::testing {

// Sets OpenCV's thread count (the pool that parallel_ranges.h runs on) for a
// scope and restores the one before.
class ThreadCount {
 public:
  explicit ThreadCount(int threads) : saved_(cv::getNumThreads()) { cv::setNumThreads(threads); }
  ~ThreadCount() { cv::setNumThreads(saved_); }
  ThreadCount(const ThreadCount&) = delete;
  ThreadCount& operator=(const ThreadCount&) = delete;

 private:
  int saved_;
};

}  // namespace areagraph::testing

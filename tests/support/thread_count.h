#pragma once

#include <opencv2/core/utility.hpp>

namespace areagraph::testing {

// Sets OpenCV's thread count (its pool runs the stages' parallel ranges) for
// a scope and restores it after.
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

#pragma once

#include <opencv2/core/utility.hpp>

namespace areagraph::testing {

// Sets OpenCV's thread count for a scope and restores it (tests that run a
// stage's compute on one pool thread and on two).
class ScopedThreadCount {
 public:
  explicit ScopedThreadCount(int threads) : saved_(cv::getNumThreads()) {
    cv::setNumThreads(threads);
  }
  ~ScopedThreadCount() { cv::setNumThreads(saved_); }
  ScopedThreadCount(const ScopedThreadCount&) = delete;
  ScopedThreadCount& operator=(const ScopedThreadCount&) = delete;

 private:
  int saved_;
};

}  // namespace areagraph::testing

// ZerosInParallel (the label raster's and path mask's clearing) on one, two
// and three threads, over sizes split into several ranges and not.
#include "stages/geometry/parallel_zeros.h"

#include <gtest/gtest.h>

#include "tests/support/thread_count.h"

namespace areagraph::testing {
namespace {

TEST(ZerosInParallelTest, EveryCellIsZeroOnAnyThreadCount) {
  for (const int threads : {1, 2, 3}) {
    ThreadCount count(threads);
    for (const cv::Size size : {cv::Size(1500, 1100), cv::Size(7, 3), cv::Size(4700, 90)}) {
      for (const int type : {CV_8U, CV_32S, CV_32F}) {
        // Garbage where the buffer may come from.
        cv::Mat(size, type, cv::Scalar(171)).release();
        const cv::Mat zeros = ZerosInParallel(size, type);
        ASSERT_EQ(zeros.size(), size);
        ASSERT_EQ(zeros.type(), type);
        EXPECT_EQ(cv::countNonZero(zeros.reshape(1)), 0) << threads << " " << size;
      }
    }
  }
}

}  // namespace
}  // namespace areagraph::testing

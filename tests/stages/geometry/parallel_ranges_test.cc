#include "stages/geometry/parallel_ranges.h"

#include <gtest/gtest.h>

#include <atomic>
#include <numeric>
#include <stdexcept>
#include <vector>

#include "tests/support/thread_count.h"

namespace areagraph {
namespace {

using testing::ThreadCount;

TEST(ParallelRangesTest, RangesCoverEveryItemOnceInOrder) {
  ThreadCount threads(2);
  for (size_t count : {0, 1, 7, 100, 1001}) {
    for (int ranges : {1, 2, 3, 8}) {
      std::vector<int> owner(count, -1);
      std::atomic<int> calls{0};
      ForEachRange(count, ranges, [&](size_t begin, size_t end, int index) {
        ++calls;
        EXPECT_EQ(begin, ParallelRangeBegin(count, ranges, index));
        EXPECT_EQ(end, ParallelRangeBegin(count, ranges, index + 1));
        for (size_t i = begin; i < end; ++i) owner[i] = index;
      });
      EXPECT_EQ(calls, count == 0 ? 0 : ranges) << count << " items, " << ranges << " ranges";
      for (size_t i = 1; i < count; ++i) ASSERT_LE(owner[i - 1], owner[i]);
      for (int o : owner) ASSERT_GE(o, 0);
    }
  }
}

TEST(ParallelRangesTest, RangeCountHonoursTheMinimumAndTheThreads) {
  {
    ThreadCount threads(2);
    EXPECT_EQ(ParallelRangeCount(10, 100), 1);
    EXPECT_EQ(ParallelRangeCount(250, 100), 2);
    EXPECT_EQ(ParallelRangeCount(1000000, 100), 8);  // four per thread
  }
  ThreadCount one(1);
  EXPECT_EQ(ParallelRangeCount(1000000, 100), 1);
}

TEST(ParallelRangesTest, MapRangesKeepsRangeOrder) {
  ThreadCount threads(2);
  std::vector<int> values(10000);
  std::iota(values.begin(), values.end(), 0);
  const auto pieces =
      MapRanges<std::vector<int>>(values.size(), 100, [&](size_t begin, size_t end) {
        return std::vector<int>(values.begin() + begin, values.begin() + end);
      });
  ASSERT_GT(pieces.size(), 1u);
  std::vector<int> joined;
  for (const auto& piece : pieces) joined.insert(joined.end(), piece.begin(), piece.end());
  EXPECT_EQ(joined, values);
}

TEST(ParallelRangesTest, ConcatRangesJoinsTheRangesInOrder) {
  ThreadCount threads(2);
  for (size_t count : {0, 1, 150, 10000}) {
    // Every third item, as one pass over [0, count) would collect them.
    std::vector<size_t> expected;
    for (size_t i = 0; i < count; i += 3) expected.push_back(i);
    const std::vector<size_t> joined =
        ConcatRanges<size_t>(count, 100, [](size_t begin, size_t end) {
          std::vector<size_t> kept;
          for (size_t i = begin; i < end; ++i) {
            if (i % 3 == 0) kept.push_back(i);
          }
          return kept;
        });
    EXPECT_EQ(joined, expected) << count << " items";
  }
}

TEST(ParallelRangesTest, ABodysExceptionReachesTheCaller) {
  ThreadCount threads(2);
  EXPECT_THROW(ForEachRange(100, 4,
                            [](size_t, size_t, int index) {
                              if (index == 2) throw std::runtime_error("range 2 failed");
                            }),
               std::runtime_error);
}

}  // namespace
}  // namespace areagraph

#pragma once

#include <algorithm>
#include <cstddef>
#include <iterator>
#include <opencv2/core/utility.hpp>
#include <vector>

namespace areagraph {

// Work split over OpenCV's thread pool (TBB on Debian; cv::setNumThreads
// sets its size) in contiguous ranges of item indices. Each range is one
// task, and callers keep per-range results in range order, so an output
// never depends on which thread ran what. One call per stage step keeps the
// pool's start-up (a few microseconds) off small maps: below `min_items`
// items per range the work runs in the caller's thread.

// How many ranges `count` items are split into: at most four per pool
// thread (so a slow range does not leave a core idle), each with at least
// `min_items` items; 1 when OpenCV runs on one thread.
inline int ParallelRangeCount(size_t count, size_t min_items) {
  const int threads = cv::getNumThreads();
  if (threads <= 1 || count < 2 * std::max<size_t>(min_items, 1)) return 1;
  const size_t by_size = count / std::max<size_t>(min_items, 1);
  return static_cast<int>(std::min<size_t>(by_size, static_cast<size_t>(threads) * 4));
}

// Item range `index` of `ranges` over [0, count): [begin, end).
inline size_t ParallelRangeBegin(size_t count, int ranges, int index) {
  return count * static_cast<size_t>(index) / static_cast<size_t>(ranges);
}

// Calls body(begin, end, range_index) once for each of `ranges` contiguous
// ranges of [0, count) (some empty when count < ranges; none when count is
// 0), in parallel; returns when all are done. An exception thrown by a body
// reaches the caller (OpenCV rethrows it).
template <typename Body>
void ForEachRange(size_t count, int ranges, const Body& body) {
  if (count == 0) return;
  if (ranges <= 1) {
    body(size_t{0}, count, 0);
    return;
  }
  cv::parallel_for_(
      cv::Range(0, ranges),
      [&](const cv::Range& r) {
        for (int i = r.start; i < r.end; ++i) {
          body(ParallelRangeBegin(count, ranges, i), ParallelRangeBegin(count, ranges, i + 1), i);
        }
      },
      ranges);
}

// body(begin, end) -> T for each range of [0, count), results in range order
// (the split of ParallelRangeCount(count, min_items)).
template <typename T, typename Body>
std::vector<T> MapRanges(size_t count, size_t min_items, const Body& body) {
  const int ranges = ParallelRangeCount(count, min_items);
  std::vector<T> results(static_cast<size_t>(ranges));
  ForEachRange(count, ranges, [&](size_t begin, size_t end, int index) {
    results[static_cast<size_t>(index)] = body(begin, end);
  });
  return results;
}

// MapRanges' per-range vectors joined in range order: the items in the
// order one pass over [0, count) gives them.
template <typename T, typename Body>
std::vector<T> ConcatRanges(size_t count, size_t min_items, const Body& body) {
  std::vector<std::vector<T>> parts = MapRanges<std::vector<T>>(count, min_items, body);
  if (parts.size() == 1) return std::move(parts[0]);
  size_t total = 0;
  for (const std::vector<T>& part : parts) total += part.size();
  std::vector<T> joined;
  joined.reserve(total);
  for (std::vector<T>& part : parts) {
    joined.insert(joined.end(), std::make_move_iterator(part.begin()),
                  std::make_move_iterator(part.end()));
  }
  return joined;
}

}  // namespace areagraph

#pragma once

#include <algorithm>
#include <chrono>
#include <functional>
#include <vector>

namespace areagraph {

// Milliseconds that `work` takes, on the steady clock.
inline double ElapsedMs(const std::function<void()>& work) {
  const auto start = std::chrono::steady_clock::now();
  work();
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
      .count();
}

// The median of `samples` (the upper one of the middle two for an even count);
// 0 for none. Medians, not means: one run disturbed by another process on a
// shared machine should not move the figure.
inline double Median(std::vector<double> samples) {
  if (samples.empty()) return 0;
  const auto middle = samples.begin() + samples.size() / 2;
  std::nth_element(samples.begin(), middle, samples.end());
  return *middle;
}

}  // namespace areagraph

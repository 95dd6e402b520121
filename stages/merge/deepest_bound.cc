#include "stages/merge/deepest_bound.h"

#include <algorithm>
#include <vector>

#include "stages/geometry/distance_transform.h"

namespace areagraph {
namespace {

// Windows overlap by this much, so that a disk up to half of it across lies
// wholly in some window.
constexpr int kOverlapCells = 256;

// The starts of windows of at most kDeepestWindowCells that cover [0, n).
std::vector<int> WindowStarts(int n) {
  std::vector<int> starts{0};
  while (starts.back() + kDeepestWindowCells < n) {
    starts.push_back(starts.back() + kDeepestWindowCells - kOverlapCells);
  }
  return starts;
}

}  // namespace

double DeepestDistanceLowerBound(const cv::Mat& mask) {
  CV_Assert(mask.type() == CV_8U);
  if (ComputedExactly(mask.size())) return DeepestDistance(mask);
  double deepest = 0;
  for (const int y : WindowStarts(mask.rows)) {
    for (const int x : WindowStarts(mask.cols)) {
      const cv::Rect box(x, y, std::min(kDeepestWindowCells, mask.cols - x),
                         std::min(kDeepestWindowCells, mask.rows - y));
      cv::Mat window = cv::Mat::zeros(box.height + 2, box.width + 2, CV_8U);
      mask(box).copyTo(window(cv::Rect(1, 1, box.width, box.height)));
      deepest = std::max(deepest, DeepestDistance(window));
    }
  }
  return deepest;
}

}  // namespace areagraph

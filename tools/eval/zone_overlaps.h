#pragma once

#include <cstdint>
#include <map>
#include <opencv2/core.hpp>
#include <utility>

namespace areagraph {

// Pixel counts of two label images of the same size: how big each segment is
// and how much each pair of segments overlaps. "Scored" pixels are those in a
// segment in both images, the only ones that enter MAORIS' MCC.
struct ZoneOverlaps {
  int64_t scored_pixels = 0;
  // Segment sizes counting only scored pixels.
  std::map<int, int64_t> result_scored;
  std::map<int, int64_t> gt_scored;
  // Segment sizes over the whole image.
  std::map<int, int64_t> result_total;
  std::map<int, int64_t> gt_total;
  // (result label, gt label) -> pixels in both; all overlaps are scored pixels.
  std::map<std::pair<int, int>, int64_t> overlap;
};

// Counts `result` against `gt` (both CV_32S, same size).
ZoneOverlaps CountZoneOverlaps(const cv::Mat& result, const cv::Mat& gt);

}  // namespace areagraph

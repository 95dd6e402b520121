#include "tools/eval/zone_overlaps.h"

#include <unordered_map>

namespace areagraph {

ZoneOverlaps CountZoneOverlaps(const cv::Mat& result, const cv::Mat& gt) {
  CV_Assert(result.type() == CV_32S && gt.type() == CV_32S && result.size() == gt.size());
  // Hash maps while scanning (maps are slow per pixel), sorted maps after.
  std::unordered_map<int, int64_t> result_total, gt_total;
  std::unordered_map<uint64_t, int64_t> pairs;
  for (int r = 0; r < result.rows; ++r) {
    const int* result_row = result.ptr<int>(r);
    const int* gt_row = gt.ptr<int>(r);
    for (int c = 0; c < result.cols; ++c) {
      const int s = result_row[c], g = gt_row[c];
      if (s != 0) ++result_total[s];
      if (g != 0) ++gt_total[g];
      if (s != 0 && g != 0) {
        ++pairs[(static_cast<uint64_t>(static_cast<uint32_t>(s)) << 32) | static_cast<uint32_t>(g)];
      }
    }
  }
  ZoneOverlaps counts;
  counts.result_total.insert(result_total.begin(), result_total.end());
  counts.gt_total.insert(gt_total.begin(), gt_total.end());
  for (const auto& [key, pixels] : pairs) {
    const int s = static_cast<int>(static_cast<uint32_t>(key >> 32));
    const int g = static_cast<int>(static_cast<uint32_t>(key & 0xffffffffu));
    counts.overlap[{s, g}] = pixels;
    counts.result_scored[s] += pixels;
    counts.gt_scored[g] += pixels;
    counts.scored_pixels += pixels;
  }
  return counts;
}

}  // namespace areagraph

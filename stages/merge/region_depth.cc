#include "stages/merge/region_depth.h"

#include <algorithm>

#include "stages/geometry/distance_transform.h"
#include "stages/geometry/region_boxes.h"

namespace areagraph {

std::vector<float> DeepestOfRegions(const cv::Mat& mask, const std::vector<CellRegion>& regions,
                                    double min_thickness_px) {
  // Each region alone in its box: the zero cells around it are the mask's
  // own (an 8-connected region touches no other) or nearer than the mask's.
  std::vector<float> deepest(regions.size(), 0);
  for (size_t k = 0; k < regions.size(); ++k) {
    const cv::Rect& box = regions[k].box;
    cv::Mat alone = cv::Mat::zeros(box.height + 2, box.width + 2, CV_8U);
    for (const cv::Point& p : regions[k].cells) {
      alone.at<uint8_t>(p.y - box.y + 1, p.x - box.x + 1) = 255;
    }
    deepest[k] = float(DeepestDistance(alone));
  }
  if (ComputedExactly(mask.size())) return deepest;
  // The rest: their rows' runs, region k as k + 1, transformed whole, as the
  // rounding of a cell depends on its whole row.
  std::vector<PieceRun> runs;
  for (size_t k = 0; k < regions.size(); ++k) {
    if (2 * deepest[k] >= min_thickness_px) continue;
    for (const cv::Point& p : regions[k].cells) {
      PieceRun* last = runs.empty() ? nullptr : &runs.back();
      if (last && last->value == int(k) + 1 && last->row == p.y && last->end == p.x) {
        ++last->end;
      } else {
        runs.push_back({p.y, p.x, p.x + 1, int(k) + 1});
      }
    }
  }
  if (runs.empty()) return deepest;
  const std::vector<float> per_run = DeepestPerRun(mask, runs, int(regions.size()) + 1);
  for (size_t k = 0; k < regions.size(); ++k) {
    if (!(2 * deepest[k] >= min_thickness_px)) deepest[k] = per_run[k + 1];
  }
  return deepest;
}

}  // namespace areagraph

#include "stages/clean/unknown_islands.h"

#include <algorithm>
#include <climits>
#include <opencv2/imgproc.hpp>

#include "proto/artifacts.pb.h"
#include "stages/clean/mask_runs.h"

namespace areagraph {

std::vector<int> FreeUnknownIslands(std::string& cells, int width, int height, double max_cells) {
  std::vector<int> freed;
  if (max_cells <= 0) return freed;
  const int count = width * height;
  cv::Mat unknown(height, width, CV_8U);
  const auto* state = reinterpret_cast<const uint8_t*>(cells.data());
  uint8_t* mask = unknown.data;  // a local pointer: the stores may alias `cells`
  for (int index = 0; index < count; ++index) {
    mask[index] = state[index] == proto::CELL_UNKNOWN ? 255 : 0;
  }
  cv::Mat labels;
  const int regions = cv::connectedComponents(unknown, labels, 8, CV_32S);
  // Boxes and sizes from the mask's runs (a run is one region's), as
  // LabelBoxes would give them, without visiting the other cells one by one.
  std::vector<int> left(regions, INT_MAX), right(regions, -1), top(regions, -1),
      bottom(regions, -1);
  std::vector<int64_t> area(regions, 0);
  for (int r = 0; r < height; ++r) {
    const int* label = labels.ptr<int>(r);
    ForEachMaskRun(unknown.ptr<uint8_t>(r), width, [&](int begin, int end) {
      const int region = label[begin];
      left[region] = std::min(left[region], begin);
      right[region] = std::max(right[region], end - 1);
      if (top[region] < 0) top[region] = r;
      bottom[region] = r;
      area[region] += end - begin;
    });
  }
  // The islands' cells, from their boxes: they are few and small.
  for (int region = 1; region < regions; ++region) {
    const bool on_border = left[region] == 0 || top[region] == 0 || right[region] == width - 1 ||
                           bottom[region] == height - 1;
    if (on_border || area[region] == 0 || double(area[region]) > max_cells) continue;
    for (int r = top[region]; r <= bottom[region]; ++r) {
      const int* label = labels.ptr<int>(r);
      for (int c = left[region]; c <= right[region]; ++c) {
        if (label[c] == region) freed.push_back(r * width + c);
      }
    }
  }
  std::sort(freed.begin(), freed.end());
  for (const int index : freed) cells[index] = proto::CELL_FREE;
  return freed;
}

}  // namespace areagraph

#include "stages/geometry/enclosed_pockets.h"

#include <algorithm>
#include <opencv2/imgproc.hpp>
#include <vector>

#include "stages/geometry/region_boxes.h"
namespace areagraph {

void FillEnclosedPockets(double max_pocket_px, cv::Mat* obstacle) {
  const int width = obstacle->cols, height = obstacle->rows;
  cv::Mat free_cells = *obstacle == 0;
  cv::Mat labels, stats;
  const int count = LabelRegionsWithBoxes(free_cells, 4, &labels, &stats);
  std::vector<uint8_t> fill(count, 0);
  for (int k = 1; k < count; ++k) {
    const int x = stats.at<int>(k, cv::CC_STAT_LEFT), y = stats.at<int>(k, cv::CC_STAT_TOP);
    const int w = stats.at<int>(k, cv::CC_STAT_WIDTH), h = stats.at<int>(k, cv::CC_STAT_HEIGHT);
    const bool border = x == 0 || y == 0 || x + w == width || y + h == height;
    fill[k] = !border && std::max(w, h) <= max_pocket_px;
  }
  for (int r = 0; r < height; ++r) {
    const int* row = labels.ptr<int>(r);
    uint8_t* target = obstacle->ptr<uint8_t>(r);
    for (int c = 0; c < width; ++c) {
      if (fill[row[c]]) target[c] = 255;
    }
  }
}

}  // namespace areagraph

#include "stages/clean/unknown_islands.h"

#include <opencv2/imgproc.hpp>

#include "proto/artifacts.pb.h"
#include "stages/geometry/region_boxes.h"

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
  cv::Mat labels, stats;
  const int regions = LabelRegionsWithBoxes(unknown, 8, &labels, &stats);
  std::vector<uint8_t> island(regions, 0);
  for (int region = 1; region < regions; ++region) {
    const int x = stats.at<int>(region, cv::CC_STAT_LEFT);
    const int y = stats.at<int>(region, cv::CC_STAT_TOP);
    const int w = stats.at<int>(region, cv::CC_STAT_WIDTH);
    const int h = stats.at<int>(region, cv::CC_STAT_HEIGHT);
    const bool on_border = x == 0 || y == 0 || x + w == width || y + h == height;
    island[region] = !on_border && stats.at<int>(region, cv::CC_STAT_AREA) <= max_cells;
  }
  const int* label = labels.ptr<int>();
  for (int index = 0; index < count; ++index) {
    if (island[label[index]]) {
      cells[index] = proto::CELL_FREE;
      freed.push_back(index);
    }
  }
  return freed;
}

}  // namespace areagraph

#include "stages/geometry/obstacle_regions.h"

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>

#include "stages/geometry/wall_thickness.h"

namespace areagraph {

ObstacleRegions FindObstacleRegions(const std::string& cells, int width, int height,
                                    const std::vector<int>& site_cells) {
  ObstacleRegions regions;
  regions.width = width;
  regions.height = height;
  const cv::Mat obstacle = ObstacleMask(cells, width, height);
  const int count = cv::connectedComponents(obstacle, regions.labels, 8, CV_32S);
  regions.depth = ObstacleDepth(obstacle);
  std::vector<RegionShape>& shapes = regions.shapes;
  shapes.resize(count);
  const int* label = regions.labels.ptr<int>();
  const float* depth_of = regions.depth.ptr<float>();
  for (int index = 0; index < width * height; ++index) {
    RegionShape& shape = shapes[label[index]];
    shape.thickness = std::max(shape.thickness, 2 * depth_of[index]);
    ++shape.cells;
    const int col = index % width, row = index / width;
    shape.on_border |= col == 0 || row == 0 || col == width - 1 || row == height - 1;
  }
  std::vector<std::vector<cv::Point2f>> outline(count);
  for (const int index : site_cells) {
    outline[label[index]].emplace_back(index % width + 0.5f, index / width + 0.5f);
  }
  for (int region = 1; region < count; ++region) {
    RegionShape& shape = shapes[region];
    if (shape.on_border || outline[region].empty()) continue;
    const cv::RotatedRect rect = cv::minAreaRect(outline[region]);
    const double angle = rect.angle * M_PI / 180;
    const Eigen::Vector2d along_width(std::cos(angle), std::sin(angle));
    const bool wide = rect.size.width >= rect.size.height;
    shape.centre = {rect.center.x, rect.center.y};
    shape.axis = wide ? along_width : Eigen::Vector2d(-along_width.y(), along_width.x());
    shape.length = std::max(rect.size.width, rect.size.height) + 1;
    shape.width = std::min(rect.size.width, rect.size.height) + 1;
  }
  return regions;
}

}  // namespace areagraph

#include "stages/geometry/obstacle_regions.h"

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>

#include "stages/geometry/region_boxes.h"
#include "stages/geometry/wall_thickness.h"

namespace areagraph {

ObstacleLabels LabelObstacles(const std::string& cells, int width, int height) {
  ObstacleLabels obstacles;
  obstacles.count = LabelRegionsWithBoxes(ObstacleMask(cells, width, height), 8, &obstacles.labels,
                                          &obstacles.stats);
  return obstacles;
}

cv::Mat LabelFreeSpaces(const std::string& cells, int width, int height) {
  cv::Mat labels;
  cv::connectedComponents(ObstacleMask(cells, width, height) == 0, labels, 4, CV_32S);
  return labels;
}

ObstacleRegions FindObstacleRegions(const std::string& cells, const ObstacleLabels& obstacles,
                                    const std::vector<int>& site_cells) {
  // The regions only read the labels: they share the buffer.
  return DescribeObstacleRegions(
      obstacles.labels, obstacles.count,
      ObstacleDepth(ObstacleMask(cells, obstacles.labels.cols, obstacles.labels.rows)), site_cells);
}

ObstacleRegions DescribeObstacleRegions(cv::Mat labels, int count, cv::Mat depth,
                                        const std::vector<int>& site_cells) {
  CV_Assert(labels.type() == CV_32S && depth.type() == CV_32F && labels.size() == depth.size());
  ObstacleRegions regions;
  const int width = regions.width = labels.cols;
  const int height = regions.height = labels.rows;
  regions.labels = std::move(labels);
  regions.depth = std::move(depth);
  std::vector<RegionShape>& shapes = regions.shapes;
  shapes.resize(count);
  for (int r = 0; r < height; ++r) {
    const int* label = regions.labels.ptr<int>(r);
    const float* depth_of = regions.depth.ptr<float>(r);
    for (int c = 0; c < width; ++c) {
      RegionShape& shape = shapes[label[c]];
      ++shape.cells;
      // Free cells (label 0) have no depth.
      if (label[c] != 0) shape.thickness = std::max(shape.thickness, 2 * depth_of[c]);
    }
  }
  for (int r = 0; r < height; ++r) {
    const int* label = regions.labels.ptr<int>(r);
    if (r == 0 || r == height - 1) {
      for (int c = 0; c < width; ++c) shapes[label[c]].on_border = true;
    } else {
      shapes[label[0]].on_border = shapes[label[width - 1]].on_border = true;
    }
  }
  const int* label = regions.labels.ptr<int>();
  std::vector<std::vector<cv::Point2f>> outline(count);
  for (const int index : site_cells) {
    outline[label[index]].emplace_back(index % width + 0.5f, index / width + 0.5f);
  }
  for (int region = 1; region < count; ++region) {
    RegionShape& shape = shapes[region];
    if (shape.on_border || outline[region].empty()) continue;
    FitRegionRectangle(outline[region], &shape);
  }
  return regions;
}

void FitRegionRectangle(const std::vector<cv::Point2f>& site_centres, RegionShape* shape) {
  const cv::RotatedRect rect = cv::minAreaRect(site_centres);
  const double angle = rect.angle * M_PI / 180;
  const Eigen::Vector2d along_width(std::cos(angle), std::sin(angle));
  const bool wide = rect.size.width >= rect.size.height;
  shape->centre = {rect.center.x, rect.center.y};
  shape->axis = wide ? along_width : Eigen::Vector2d(-along_width.y(), along_width.x());
  shape->length = std::max(rect.size.width, rect.size.height) + 1;
  shape->width = std::min(rect.size.width, rect.size.height) + 1;
}

}  // namespace areagraph

#pragma once

#include <Eigen/Core>
#include <cmath>
#include <cstdint>
#include <opencv2/core.hpp>
#include <string>
#include <vector>

namespace areagraph {

// The shape of one 8-connected region of non-free cells.
struct RegionShape {
  bool on_border = false;
  // Twice the depth of the deepest cell (px).
  float thickness = 0;
  int64_t cells = 0;
  // The smallest rotated rectangle around its site cells: centre, unit
  // vector along its longer side, and its sides (px). Zero for regions on
  // the image border and regions without site cells.
  Eigen::Vector2d centre = Eigen::Vector2d::Zero();
  Eigen::Vector2d axis = Eigen::Vector2d::UnitX();
  float length = 0;
  float width = 0;
};

// A map's non-free cells, their 8-connected regions (label 0 = free) and
// their depth (ObstacleDepth).
struct ObstacleRegions {
  int width = 0;
  int height = 0;
  cv::Mat labels;
  cv::Mat depth;
  std::vector<RegionShape> shapes;

  bool NonFree(const Eigen::Vector2d& p) const {
    const int c = static_cast<int>(std::floor(p.x())), r = static_cast<int>(std::floor(p.y()));
    return c >= 0 && r >= 0 && c < width && r < height && labels.at<int>(r, c) != 0;
  }
  int LabelAt(const Eigen::Vector2d& p) const {
    const int c = static_cast<int>(std::floor(p.x())), r = static_cast<int>(std::floor(p.y()));
    return c >= 0 && r >= 0 && c < width && r < height ? labels.at<int>(r, c) : 0;
  }
};

// A map's non-free cells as 8-connected regions: the labels of
// cv::connectedComponents on ObstacleMask (label 0 = free), and each
// region's box and cells (LabelRegionsWithBoxes' stats). Labelled once
// for all of cut's site finders.
struct ObstacleLabels {
  cv::Mat labels;
  cv::Mat stats;
  int count = 0;
};
ObstacleLabels LabelObstacles(const std::string& cells, int width, int height);

// The map's free cells as 4-connected spaces, as the free space is
// connected (CV_32S labels, 0 = non-free): cells in different spaces
// cannot reach each other.
cv::Mat LabelFreeSpaces(const std::string& cells, int width, int height);

// The regions of `cells` (labelled as `obstacles`); the rectangles are
// fitted to `site_cells` (flat indices of non-free cells, such as
// ObstacleSiteCells: the cells next to free space span the same rectangle
// as the whole region). Regions without any of them get no rectangle.
ObstacleRegions FindObstacleRegions(const std::string& cells, const ObstacleLabels& obstacles,
                                    const std::vector<int>& site_cells);

// The same from the regions' labels (`count` of them, as cv::connectedComponents
// labels ObstacleMask with connectivity 8) and their depth, for a caller that
// has labelled them already.
ObstacleRegions DescribeObstacleRegions(cv::Mat labels, int count, cv::Mat depth,
                                        const std::vector<int>& site_cells);

// The rectangle of a region (centre, axis, length, width) from its site
// cells' centres, as DescribeObstacleRegions fits it (cv::minAreaRect).
void FitRegionRectangle(const std::vector<cv::Point2f>& site_centres, RegionShape* shape);

}  // namespace areagraph

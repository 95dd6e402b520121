#include "stages/clean/furniture_removal.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <opencv2/imgproc.hpp>

#include "stages/geometry/alpha_shape.h"
#include "stages/geometry/cell_states.h"
#include "stages/geometry/disjoint_sets.h"

namespace areagraph {
namespace {

// 8-connected regions of non-free cells: label per cell (0 = free) and the
// number of labels including 0.
int LabelObstacleRegions(const std::string& cells, int width, int height, cv::Mat* labels) {
  cv::Mat obstacle(height, width, CV_8U);
  for (int index = 0; index < width * height; ++index) {
    obstacle.data[index] = cells[index] == proto::CELL_FREE ? 0 : 255;
  }
  return cv::connectedComponents(obstacle, *labels, 8, CV_32S);
}

// Regions that belong to the map's outline: those touching the image border
// and those too big for furniture.
std::vector<bool> OutlineRegions(int width, int height, const cv::Mat& labels, int region_count,
                                 double max_region_cells) {
  std::vector<bool> outline(region_count, false);
  std::vector<int> size(region_count, 0);
  const int* label = labels.ptr<int>();
  for (int row = 0; row < height; ++row) {
    for (int col = 0; col < width; ++col) {
      const int region = label[row * width + col];
      if (region == 0) continue;
      ++size[region];
      if (row == 0 || col == 0 || row == height - 1 || col == width - 1) outline[region] = true;
    }
  }
  for (int region = 1; region < region_count; ++region) {
    if (size[region] > max_region_cells) outline[region] = true;
  }
  return outline;
}

proto::Polygon ConvexOutline(const std::vector<int>& cell_indices, int width) {
  std::vector<cv::Point> corners;
  corners.reserve(4 * cell_indices.size());
  for (const int index : cell_indices) {
    const int col = index % width;
    const int row = index / width;
    corners.insert(corners.end(), {{col, row}, {col + 1, row}, {col + 1, row + 1}, {col, row + 1}});
  }
  std::vector<cv::Point> hull;
  cv::convexHull(corners, hull);
  proto::Polygon polygon;
  for (const cv::Point& corner : hull) {
    proto::Point2* point = polygon.mutable_outer()->add_points();
    point->set_x(corner.x);
    point->set_y(corner.y);
  }
  return polygon;
}

}  // namespace

double MaxFurnitureRegionCells(double alpha_radius_px, double max_perimeter_px) {
  if (alpha_radius_px < 1) return std::numeric_limits<double>::infinity();
  const double p = max_perimeter_px;
  return 2 * (p * p / (4 * M_PI) + p) + 16;
}

FurnitureRemoval RemoveFurniture(std::string& cells, int width, int height, double alpha_radius_px,
                                 double max_perimeter_px) {
  cv::Mat labels;
  const int region_count = LabelObstacleRegions(cells, width, height, &labels);
  const std::vector<bool> outline =
      OutlineRegions(width, height, labels, region_count,
                     MaxFurnitureRegionCells(alpha_radius_px, max_perimeter_px));
  const int* label = labels.ptr<int>();

  const CellStates grid(cells, width, height);
  std::vector<int> point_cells;
  std::vector<Eigen::Vector2d> points;
  for (int row = 0; row < height; ++row) {
    for (int col = 0; col < width; ++col) {
      const int index = row * width + col;
      if (label[index] == 0) continue;
      if (outline[label[index]] && !grid.TouchesFree(col, row)) continue;
      point_cells.push_back(index);
      points.push_back(CellCentre(col, row));
    }
  }
  FurnitureRemoval removal;
  if (points.empty()) return removal;

  // Pieces: alpha-shape components joined through shared obstacle regions.
  const AlphaComplex complex = ComputeAlphaComplex(points, alpha_radius_px);
  const std::vector<double> component_perimeters = ComponentPerimeters(points, complex);
  DisjointSets pieces(complex.component_count);
  std::vector<int> component_of_region(region_count, -1);
  for (size_t p = 0; p < points.size(); ++p) {
    int& first = component_of_region[label[point_cells[p]]];
    if (first < 0) first = complex.component_of_point[p];
    pieces.Union(first, complex.component_of_point[p]);
  }
  int piece_count = 0;
  const std::vector<int> piece_of_component = pieces.DenseLabels(&piece_count);
  std::vector<double> perimeter(piece_count, 0.0);
  for (int c = 0; c < complex.component_count; ++c) {
    perimeter[piece_of_component[c]] += component_perimeters[c];
  }
  std::vector<bool> is_outline(piece_count, false);
  for (int region = 1; region < region_count; ++region) {
    if (outline[region] && component_of_region[region] >= 0) {
      is_outline[piece_of_component[component_of_region[region]]] = true;
    }
  }

  // Every cell of a furniture piece's regions becomes free.
  std::vector<std::vector<int>> piece_cells(piece_count);
  for (int index = 0; index < width * height; ++index) {
    if (label[index] == 0 || outline[label[index]]) continue;
    const int piece = piece_of_component[component_of_region[label[index]]];
    if (is_outline[piece] || perimeter[piece] >= max_perimeter_px) continue;
    piece_cells[piece].push_back(index);
  }
  for (const std::vector<int>& piece : piece_cells) {
    if (piece.empty()) continue;
    for (const int index : piece) cells[index] = proto::CELL_FREE;
    removal.removed_cells.insert(removal.removed_cells.end(), piece.begin(), piece.end());
    removal.shapes.push_back(ConvexOutline(piece, width));
  }
  std::sort(removal.removed_cells.begin(), removal.removed_cells.end());
  return removal;
}

}  // namespace areagraph

#include "stages/clean/furniture_removal.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <opencv2/imgproc.hpp>

#include "stages/clean/alpha_pieces.h"
#include "stages/clean/cell_runs.h"
#include "stages/clean/mask_runs.h"
#include "stages/geometry/cell_states.h"

namespace areagraph {
namespace {

// 8-connected regions of non-free cells (`obstacles`, over their runs) and
// their labels per cell (0 = free, run region r is label r + 1), and for each
// label 1 when it belongs to the map's outline: touching the image border,
// or too big for furniture. Label 0 is never outline.
std::vector<uint8_t> LabelObstacleRegions(const std::string& cells, int width, int height,
                                          double max_region_cells, RunRegions* obstacles,
                                          cv::Mat* labels) {
  static_assert(proto::CELL_FREE == 0, "non-free cells have a bit of 3 set");
  *obstacles = FindRunRegions(cells, width, height, proto::CELL_OCCUPIED | proto::CELL_UNKNOWN);
  const int region_count = obstacles->count + 1;
  // Every cell written once: the runs' labels, zeros between them.
  labels->create(height, width, CV_32S);
  std::vector<int> size(region_count, 0);
  std::vector<uint8_t> outline(region_count, 0);
  int* cell = labels->ptr<int>();
  int* written = cell;
  for (size_t i = 0; i < obstacles->runs.size(); ++i) {
    const CellRun& run = obstacles->runs[i];
    const int label = obstacles->region[i] + 1;
    int* row = cell + size_t(run.row) * width;
    written = std::fill_n(written, row + run.begin - written, 0);
    written = std::fill_n(written, run.end - run.begin, label);
    size[label] += run.end - run.begin;
    outline[label] |= OnBorder(run, width, height);
  }
  std::fill(written, cell + size_t(width) * height, 0);
  for (int region = 1; region < region_count; ++region) {
    outline[region] |= size[region] > max_region_cells;
  }
  return outline;
}

// The cells that enter the alpha shape, in row-major order: every cell of the
// regions that may be furniture, and the outline's cells next to free space
// within `reach` (the disk's diameter) of such a cell. Alpha-shape components
// are those of the union of the disks around the points (its nerve), so
// points farther apart never join, and the shape of a piece out of reach of
// all other points is the same without them: the outline's other cells cannot
// change what is furniture. No cells when no region may be furniture.
std::vector<int> AlphaShapeCells(const std::string& cells, int width, int height,
                                 const RunRegions& obstacles, const cv::Mat& labels,
                                 const std::vector<uint8_t>& outline, double reach) {
  std::vector<int> inner;
  cv::Rect inner_box;
  for (size_t i = 0; i < obstacles.runs.size(); ++i) {
    if (outline[obstacles.region[i] + 1]) continue;
    const CellRun& run = obstacles.runs[i];
    for (int col = run.begin; col < run.end; ++col) inner.push_back(run.row * width + col);
    inner_box |= cv::Rect(run.begin, run.row, run.end - run.begin, 1);
  }
  if (inner.empty()) return {};
  // Within a square around the inner cells: a little more than the reach.
  // Only the inner cells' box and that margin around it can be: the
  // dilation works there (outside the box, as outside the image, are zeros).
  const int margin = int(std::ceil(reach)) + 1;
  const cv::Rect box = cv::Rect(inner_box.x - margin, inner_box.y - margin,
                                inner_box.width + 2 * margin, inner_box.height + 2 * margin) &
                       cv::Rect(0, 0, width, height);
  cv::Mat inner_mask(box.size(), CV_8U, cv::Scalar(0));
  for (const int index : inner)
    inner_mask.at<uint8_t>(index / width - box.y, index % width - box.x) = 255;
  cv::Mat within_reach;
  cv::dilate(inner_mask, within_reach,
             cv::getStructuringElement(cv::MORPH_RECT, cv::Size(2 * margin + 1, 2 * margin + 1)));

  const CellStates grid(cells, width, height);
  std::vector<int> edge;
  for (int row = box.y; row < box.y + box.height; ++row) {
    const int* label = labels.ptr<int>(row) + box.x;
    ForEachMaskRun(within_reach.ptr<uint8_t>(row - box.y), box.width, [&](int begin, int end) {
      for (int c = begin; c < end; ++c) {
        if (label[c] != 0 && outline[label[c]] && grid.TouchesFree(box.x + c, row)) {
          edge.push_back(row * width + box.x + c);
        }
      }
    });
  }
  std::vector<int> merged(inner.size() + edge.size());
  std::merge(inner.begin(), inner.end(), edge.begin(), edge.end(), merged.begin());
  return merged;
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
                                 double max_perimeter_px, const WallPieceSizes* wall_pieces) {
  RunRegions obstacles;
  cv::Mat labels;
  const std::vector<uint8_t> outline = LabelObstacleRegions(
      cells, width, height, MaxFurnitureRegionCells(alpha_radius_px, max_perimeter_px), &obstacles,
      &labels);
  const int region_count = int(outline.size());
  const int* label = labels.ptr<int>();

  const std::vector<int> point_cells =
      AlphaShapeCells(cells, width, height, obstacles, labels, outline, 2 * alpha_radius_px);
  FurnitureRemoval removal;
  if (point_cells.empty()) return removal;
  FurniturePieces pieces;
  if (!FurniturePiecesByClusters(point_cells, width, height, label, outline, alpha_radius_px,
                                 max_perimeter_px, &pieces)) {
    pieces = FurniturePiecesOfWholeShape(point_cells, width, label, outline, alpha_radius_px,
                                         max_perimeter_px);
  }

  // Every cell of a furniture piece's regions becomes free. Regions that are
  // not outline entered the alpha shape in full, so their cells are points.
  std::vector<int> furniture_cells;
  std::vector<int> furniture_piece;
  for (size_t p = 0; p < point_cells.size(); ++p) {
    if (pieces.piece_of_point[p] < 0) continue;
    furniture_cells.push_back(point_cells[p]);
    furniture_piece.push_back(pieces.piece_of_point[p]);
  }
  // Pieces of wall stay.
  std::vector<uint8_t> wall_piece;
  if (wall_pieces != nullptr && !furniture_cells.empty()) {
    wall_piece =
        WallPieceRegions(cells, width, height, labels, region_count, furniture_cells, *wall_pieces);
  }
  std::vector<std::vector<int>> piece_cells(pieces.count);
  for (size_t i = 0; i < furniture_cells.size(); ++i) {
    const int index = furniture_cells[i];
    if (!wall_piece.empty() && wall_piece[label[index]]) continue;
    piece_cells[furniture_piece[i]].push_back(index);
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

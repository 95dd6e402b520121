#include "stages/merge/area_raster.h"

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>

#include "stages/geometry/polygon_raster.h"

namespace areagraph {
namespace {

constexpr int kDx[4] = {1, -1, 0, 0};
constexpr int kDy[4] = {0, 0, 1, -1};

// Label of the cells that free space the graph never reached claims while
// growing; cleared to 0 afterwards.
constexpr int kUnreached = -1;

// The 4-neighbours of cell `index` (row-major in a cols x rows grid) in the
// order +x, -x, +y, -y, or -1 where one would leave the grid.
inline void Neighbours(int index, int cols, int rows, int neighbours[4]) {
  const int c = index % cols, r = index / cols;
  neighbours[0] = c + 1 < cols ? index + 1 : -1;
  neighbours[1] = c > 0 ? index - 1 : -1;
  neighbours[2] = r + 1 < rows ? index + cols : -1;
  neighbours[3] = r > 0 ? index - cols : -1;
}

// Breadth-first growth of all labels (kUnreached too) into unlabelled domain
// cells, seeded in row-major order: a flat queue of cell indices over the
// continuous matrices, linear in the grid.
void GrowLabels(const cv::Mat& domain, cv::Mat* labels) {
  CV_Assert(domain.isContinuous() && labels->isContinuous());
  const int cols = labels->cols, rows = labels->rows;
  const uint8_t* inside = domain.ptr<uint8_t>();
  int* label = labels->ptr<int>();
  std::vector<int> queue;
  for (int i = 0; i < cols * rows; ++i) {
    if (label[i] != 0) queue.push_back(i);
  }
  int neighbours[4];
  for (size_t head = 0; head < queue.size(); ++head) {
    const int p = queue[head];
    Neighbours(p, cols, rows, neighbours);
    for (int q : neighbours) {
      if (q < 0 || !inside[q] || label[q] != 0) continue;
      label[q] = label[p];
      queue.push_back(q);
    }
  }
}

// Clears every cell that is not in the main 4-connected piece of its label:
// the piece with most of the area's path cells (`on_path`), else the biggest.
void KeepMainPieces(const cv::Mat& on_path, cv::Mat* labels, int label_count) {
  CV_Assert(on_path.isContinuous() && labels->isContinuous());
  const int cols = labels->cols, rows = labels->rows;
  const uint8_t* path = on_path.ptr<uint8_t>();
  const int* label = labels->ptr<int>();
  cv::Mat piece_mat(labels->size(), CV_32S, cv::Scalar(-1));
  int* piece = piece_mat.ptr<int>();
  std::vector<int64_t> piece_size;
  std::vector<int64_t> piece_path;
  std::vector<int> piece_label;
  std::vector<int> queue;
  int neighbours[4];
  for (int start = 0; start < cols * rows; ++start) {
    if (label[start] <= 0 || piece[start] >= 0) continue;
    const int id = static_cast<int>(piece_size.size());
    piece_size.push_back(0);
    piece_path.push_back(0);
    piece_label.push_back(label[start]);
    queue.assign(1, start);
    piece[start] = id;
    for (size_t head = 0; head < queue.size(); ++head) {
      const int p = queue[head];
      ++piece_size[id];
      piece_path[id] += path[p] != 0;
      Neighbours(p, cols, rows, neighbours);
      for (int q : neighbours) {
        if (q < 0 || label[q] != label[start] || piece[q] >= 0) continue;
        piece[q] = id;
        queue.push_back(q);
      }
    }
  }
  std::vector<int> biggest(label_count + 1, -1);
  for (size_t id = 0; id < piece_size.size(); ++id) {
    int& best = biggest[piece_label[id]];
    if (best < 0 || piece_path[id] > piece_path[best] ||
        (piece_path[id] == piece_path[best] && piece_size[id] > piece_size[best])) {
      best = static_cast<int>(id);
    }
  }
  int* writable = labels->ptr<int>();
  for (int i = 0; i < cols * rows; ++i) {
    if (writable[i] > 0 && biggest[writable[i]] != piece[i]) writable[i] = 0;
  }
}

// Marks kUnreached on the unlabelled cells of the cores (free cells at least
// min_gap_px / 2 from any non-free cell, 4-connected pieces) that no area's
// polygons or paths reach and that are big enough to be a room.
void MarkUnreachedCores(const CellGrid& grid, const cv::Mat& domain, double min_gap_px,
                        cv::Mat* labels) {
  cv::Mat free_cells(labels->size(), CV_8U);
  for (int r = 0; r < free_cells.rows; ++r) {
    uint8_t* row = free_cells.ptr<uint8_t>(r);
    for (int c = 0; c < free_cells.cols; ++c) row[c] = grid.IsFree(c, r) ? 255 : 0;
  }
  cv::Mat distance;
  cv::distanceTransform(free_cells, distance, cv::DIST_L2, cv::DIST_MASK_PRECISE);
  cv::Mat core = (distance >= 0.5 * min_gap_px) & (domain != 0);
  cv::Mat pieces;
  const int count = cv::connectedComponents(core, pieces, 4, CV_32S);
  std::vector<uint8_t> reached(count, 0);
  std::vector<int64_t> size(count, 0);
  for (int r = 0; r < pieces.rows; ++r) {
    for (int c = 0; c < pieces.cols; ++c) {
      const int piece = pieces.at<int>(r, c);
      ++size[piece];
      if (labels->at<int>(r, c) > 0) reached[piece] = 1;
    }
  }
  // Pockets in clutter are no room: a core must span (2 gaps)^2 to stay unreached.
  const double min_core_cells = 4 * min_gap_px * min_gap_px;
  for (int piece = 1; piece < count; ++piece) {
    if (size[piece] < min_core_cells) reached[piece] = 1;
  }
  for (int r = 0; r < pieces.rows; ++r) {
    for (int c = 0; c < pieces.cols; ++c) {
      const int piece = pieces.at<int>(r, c);
      int& label = labels->at<int>(r, c);
      if (piece > 0 && !reached[piece] && label == 0) label = kUnreached;
    }
  }
}

void CountCells(AreaRaster* raster) {
  std::fill(raster->cell_count.begin(), raster->cell_count.end(), 0);
  for (int r = 0; r < raster->labels.rows; ++r) {
    const int* row = raster->labels.ptr<int>(r);
    for (int c = 0; c < raster->labels.cols; ++c) {
      if (row[c] > 0) ++raster->cell_count[row[c] - 1];
    }
  }
}

}  // namespace

AreaRaster PartitionFreeSpace(const CellGrid& grid, const cv::Mat& boundary_mask,
                              const std::vector<std::vector<const proto::Polygon*>>& area_polygons,
                              const std::vector<std::vector<PointList>>& area_paths,
                              const std::vector<std::pair<PointList, int>>& through_paths,
                              double min_gap_px, const cv::Mat& keep_out) {
  const cv::Size size(grid.width(), grid.height());
  cv::Mat domain = boundary_mask.clone();
  AreaRaster raster;
  for (int r = 0; r < size.height; ++r) {
    uint8_t* row = domain.ptr<uint8_t>(r);
    for (int c = 0; c < size.width; ++c) {
      const bool kept_out = !keep_out.empty() && keep_out.at<uint8_t>(r, c) != 0;
      row[c] = row[c] && grid.IsFree(c, r) && !kept_out ? 1 : 0;
      raster.domain_cells += row[c];
    }
  }
  raster.labels = cv::Mat::zeros(size, CV_32S);
  for (size_t k = 0; k < area_polygons.size(); ++k) {
    for (const proto::Polygon* polygon : area_polygons[k]) {
      FillPolygon(*polygon, static_cast<int>(k) + 1, &raster.labels);
    }
  }
  cv::Mat on_path = cv::Mat::zeros(size, CV_8U);
  // 4-connected, so that an area's paths hold its pieces together.
  auto draw_path = [&](const PointList& path, int area) {
    std::vector<cv::Point> cells;
    for (const Eigen::Vector2d& p : path) {
      cells.emplace_back(static_cast<int>(std::floor(p.x())), static_cast<int>(std::floor(p.y())));
    }
    cv::polylines(raster.labels, cells, /*isClosed=*/false, cv::Scalar(area + 1), 1, cv::LINE_4);
    cv::polylines(on_path, cells, /*isClosed=*/false, cv::Scalar(1), 1, cv::LINE_4);
  };
  for (size_t k = 0; k < area_paths.size(); ++k) {
    for (const PointList& path : area_paths[k]) draw_path(path, static_cast<int>(k));
  }
  for (const auto& [path, area] : through_paths) draw_path(path, area);
  raster.labels.setTo(0, domain == 0);
  if (min_gap_px > 0) MarkUnreachedCores(grid, domain, min_gap_px, &raster.labels);
  GrowLabels(domain, &raster.labels);
  KeepMainPieces(on_path, &raster.labels, static_cast<int>(area_polygons.size()));
  GrowLabels(domain, &raster.labels);
  raster.labels.setTo(0, raster.labels == kUnreached);
  raster.cell_count.assign(area_polygons.size(), 0);
  CountCells(&raster);
  return raster;
}

std::vector<cv::Rect> AreaBoxes(const AreaRaster& raster) {
  std::vector<cv::Rect> box(raster.cell_count.size());
  for (int r = 0; r < raster.labels.rows; ++r) {
    const int* row = raster.labels.ptr<int>(r);
    for (int c = 0; c < raster.labels.cols; ++c) {
      if (row[c] <= 0) continue;
      cv::Rect& b = box[row[c] - 1];
      b = b.area() == 0 ? cv::Rect(c, r, 1, 1) : (b | cv::Rect(c, r, 1, 1));
    }
  }
  return box;
}

}  // namespace areagraph

#include "stages/merge/area_raster.h"

#include <algorithm>
#include <cmath>
#include <deque>
#include <map>
#include <opencv2/imgproc.hpp>

#include "stages/geometry/polygon_raster.h"

namespace areagraph {
namespace {

constexpr int kDx[4] = {1, -1, 0, 0};
constexpr int kDy[4] = {0, 0, 1, -1};

// Breadth-first growth of all labels into unlabelled domain cells.
void GrowLabels(const cv::Mat& domain, cv::Mat* labels) {
  std::deque<cv::Point> queue;
  for (int r = 0; r < labels->rows; ++r) {
    const int* row = labels->ptr<int>(r);
    for (int c = 0; c < labels->cols; ++c) {
      if (row[c] > 0) queue.emplace_back(c, r);
    }
  }
  while (!queue.empty()) {
    const cv::Point p = queue.front();
    queue.pop_front();
    const int label = labels->at<int>(p);
    for (int k = 0; k < 4; ++k) {
      const cv::Point q(p.x + kDx[k], p.y + kDy[k]);
      if (q.x < 0 || q.y < 0 || q.x >= labels->cols || q.y >= labels->rows) continue;
      if (!domain.at<uint8_t>(q) || labels->at<int>(q) != 0) continue;
      labels->at<int>(q) = label;
      queue.push_back(q);
    }
  }
}

// Clears every cell that is not in the main 4-connected piece of its label:
// the piece with most of the area's path cells (`on_path`), else the biggest.
void KeepMainPieces(const cv::Mat& on_path, cv::Mat* labels, int label_count) {
  cv::Mat piece(labels->size(), CV_32S, cv::Scalar(-1));
  std::vector<int64_t> piece_size;
  std::vector<int64_t> piece_path;
  std::vector<int> piece_label;
  for (int r = 0; r < labels->rows; ++r) {
    for (int c = 0; c < labels->cols; ++c) {
      const int label = labels->at<int>(r, c);
      if (label == 0 || piece.at<int>(r, c) >= 0) continue;
      const int id = static_cast<int>(piece_size.size());
      piece_size.push_back(0);
      piece_path.push_back(0);
      piece_label.push_back(label);
      std::deque<cv::Point> queue{cv::Point(c, r)};
      piece.at<int>(r, c) = id;
      while (!queue.empty()) {
        const cv::Point p = queue.front();
        queue.pop_front();
        ++piece_size[id];
        piece_path[id] += on_path.at<uint8_t>(p) != 0;
        for (int k = 0; k < 4; ++k) {
          const cv::Point q(p.x + kDx[k], p.y + kDy[k]);
          if (q.x < 0 || q.y < 0 || q.x >= labels->cols || q.y >= labels->rows) continue;
          if (labels->at<int>(q) != label || piece.at<int>(q) >= 0) continue;
          piece.at<int>(q) = id;
          queue.push_back(q);
        }
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
  for (int r = 0; r < labels->rows; ++r) {
    for (int c = 0; c < labels->cols; ++c) {
      int& label = labels->at<int>(r, c);
      if (label > 0 && biggest[label] != piece.at<int>(r, c)) label = 0;
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

AreaRaster PartitionFreeSpace(const CellGrid& grid, const proto::Polygon& boundary,
                              const std::vector<std::vector<const proto::Polygon*>>& area_polygons,
                              const std::vector<std::vector<PointList>>& area_paths,
                              const std::vector<std::pair<PointList, int>>& through_paths) {
  const cv::Size size(grid.width(), grid.height());
  cv::Mat domain = PolygonMask(boundary, size);
  AreaRaster raster;
  for (int r = 0; r < size.height; ++r) {
    uint8_t* row = domain.ptr<uint8_t>(r);
    for (int c = 0; c < size.width; ++c) {
      row[c] = row[c] && grid.IsFree(c, r) ? 1 : 0;
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
  GrowLabels(domain, &raster.labels);
  KeepMainPieces(on_path, &raster.labels, static_cast<int>(area_polygons.size()));
  GrowLabels(domain, &raster.labels);
  raster.cell_count.assign(area_polygons.size(), 0);
  CountCells(&raster);
  return raster;
}

void MergeAreaCells(int from, int into, AreaRaster* raster) {
  const int from_label = from + 1, into_label = into + 1;
  for (int r = 0; r < raster->labels.rows; ++r) {
    int* row = raster->labels.ptr<int>(r);
    for (int c = 0; c < raster->labels.cols; ++c) {
      if (row[c] == from_label) row[c] = into_label;
      if (row[c] > from_label) --row[c];
    }
  }
  raster->cell_count[into] += raster->cell_count[from];
  raster->cell_count.erase(raster->cell_count.begin() + from);
}

std::vector<std::pair<int64_t, int64_t>> SharedBorders(const AreaRaster& raster) {
  const int64_t count = static_cast<int64_t>(raster.cell_count.size());
  std::map<int64_t, int64_t> borders;
  const cv::Mat& labels = raster.labels;
  for (int r = 0; r < labels.rows; ++r) {
    for (int c = 0; c < labels.cols; ++c) {
      const int a = labels.at<int>(r, c);
      if (a == 0) continue;
      const int right = c + 1 < labels.cols ? labels.at<int>(r, c + 1) : 0;
      const int below = r + 1 < labels.rows ? labels.at<int>(r + 1, c) : 0;
      for (const int b : {right, below}) {
        if (b == 0 || b == a) continue;
        const int64_t lo = std::min(a, b) - 1, hi = std::max(a, b) - 1;
        ++borders[lo * count + hi];
      }
    }
  }
  return {borders.begin(), borders.end()};
}

}  // namespace areagraph

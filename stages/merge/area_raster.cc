#include "stages/merge/area_raster.h"

#include <algorithm>
#include <cmath>
#include <deque>
#include <opencv2/imgproc.hpp>

#include "stages/geometry/distance_transform.h"
#include "stages/geometry/polygon_raster.h"
#include "stages/geometry/region_boxes.h"

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
// cells, seeded in row-major order, linear in the grid. Only labelled cells
// beside an unlabelled domain cell are seeded (the others would add nothing
// when their turn came, since labels are only ever set), and the queue lets
// go of what it has handled, so it holds the growing front, not the map.
void GrowLabels(const cv::Mat& domain, cv::Mat* labels) {
  CV_Assert(domain.isContinuous() && labels->isContinuous());
  const int cols = labels->cols, rows = labels->rows;
  const uint8_t* inside = domain.ptr<uint8_t>();
  int* label = labels->ptr<int>();
  auto open = [&](int q) { return q >= 0 && inside[q] && label[q] == 0; };
  std::deque<int> queue;
  int neighbours[4];
  // Row by row, so that no cell's row and column are divided out.
  for (int r = 0; r < rows; ++r) {
    const int first = r * cols;
    for (int c = 0; c < cols; ++c) {
      const int i = first + c;
      if (label[i] == 0) continue;
      if ((c + 1 < cols && open(i + 1)) || (c > 0 && open(i - 1)) ||
          (r + 1 < rows && open(i + cols)) || (r > 0 && open(i - cols))) {
        queue.push_back(i);
      }
    }
  }
  while (!queue.empty()) {
    const int p = queue.front();
    queue.pop_front();
    Neighbours(p, cols, rows, neighbours);
    for (int q : neighbours) {
      if (!open(q)) continue;
      label[q] = label[p];
      queue.push_back(q);
    }
  }
}

// Marks the cells of a piece while KeepMainPieces walks it; no area label
// reaches this bit.
constexpr int kVisited = 1 << 30;

// Visits the 4-connected piece of cells equal to `value` around `start`
// (breadth first), sets each to `mark` and calls visit(cell) on it. For the
// int labels and the byte core mask alike.
template <typename Cell, typename Visit>
void WalkPiece(int start, Cell value, Cell mark, int cols, int rows, Cell* label, Visit visit) {
  std::deque<int> queue(1, start);
  label[start] = mark;
  int neighbours[4];
  while (!queue.empty()) {
    const int p = queue.front();
    queue.pop_front();
    visit(p);
    Neighbours(p, cols, rows, neighbours);
    for (int q : neighbours) {
      if (q < 0 || label[q] != value) continue;
      label[q] = mark;
      queue.push_back(q);
    }
  }
}

// Clears every cell that is not in the main 4-connected piece of its label:
// the piece with most of the area's path cells (`on_path`), else the biggest.
// Pieces are marked in the labels themselves (kVisited), not in a second
// raster.
void KeepMainPieces(const cv::Mat& on_path, cv::Mat* labels, int label_count) {
  CV_Assert(on_path.isContinuous() && labels->isContinuous());
  const int cols = labels->cols, rows = labels->rows;
  const uint8_t* path = on_path.ptr<uint8_t>();
  int* label = labels->ptr<int>();
  struct Piece {
    int start;
    int label;
    int64_t size = 0;
    int64_t path = 0;
  };
  std::vector<Piece> pieces;
  for (int start = 0; start < cols * rows; ++start) {
    if (label[start] <= 0 || (label[start] & kVisited) != 0) continue;
    Piece piece{start, label[start]};
    WalkPiece(start, piece.label, piece.label | kVisited, cols, rows, label, [&](int p) {
      ++piece.size;
      piece.path += path[p] != 0;
    });
    pieces.push_back(piece);
  }
  std::vector<int> biggest(label_count + 1, -1);
  for (size_t id = 0; id < pieces.size(); ++id) {
    const Piece& piece = pieces[id];
    int& best = biggest[piece.label];
    if (best < 0 || piece.path > pieces[best].path ||
        (piece.path == pieces[best].path && piece.size > pieces[best].size)) {
      best = static_cast<int>(id);
    }
  }
  for (size_t id = 0; id < pieces.size(); ++id) {
    const Piece& piece = pieces[id];
    if (biggest[piece.label] == static_cast<int>(id)) continue;
    WalkPiece(piece.start, piece.label | kVisited, 0, cols, rows, label, [](int) {});
  }
  for (int i = 0; i < cols * rows; ++i) {
    if (label[i] > 0) label[i] &= ~kVisited;
  }
}

// The cores: domain cells at least min_gap_px / 2 from any non-free cell
// (1, else 0).
cv::Mat CoreCells(const CellGrid& grid, const cv::Mat& domain, double min_gap_px) {
  cv::Mat cells(domain.size(), CV_8U);
  for (int r = 0; r < cells.rows; ++r) {
    uint8_t* row = cells.ptr<uint8_t>(r);
    const uint8_t* state = grid.CellRow(r);
    for (int c = 0; c < cells.cols; ++c) row[c] = state[c] == proto::CELL_FREE ? 255 : 0;
  }
  // Only the threshold is asked: no distances.
  cv::Mat core = DistanceAtLeast(cells, static_cast<float>(0.5 * min_gap_px));
  for (int r = 0; r < core.rows; ++r) {
    uint8_t* row = core.ptr<uint8_t>(r);
    const uint8_t* inside = domain.ptr<uint8_t>(r);
    for (int c = 0; c < core.cols; ++c) row[c] = row[c] != 0 && inside[c] != 0 ? 1 : 0;
  }
  return core;
}

// Marks kUnreached on the unlabelled cells of the cores (`core`, see
// CoreCells; consumed as visit marks) whose 4-connected pieces no area's
// polygons or paths reach and that are big enough to be a room.
void MarkUnreachedCores(cv::Mat core, double min_gap_px, cv::Mat* labels) {
  CV_Assert(core.isContinuous() && labels->isContinuous());
  const int cols = labels->cols, rows = labels->rows;
  uint8_t* cell = core.ptr<uint8_t>();
  int* label = labels->ptr<int>();
  // Pockets in clutter are no room: a core must span (2 gaps)^2 to stay unreached.
  const double min_core_cells = 4 * min_gap_px * min_gap_px;
  enum : uint8_t { kCore = 1, kSeen = 2, kDone = 3 };
  // Walks the piece of `from` cells around `start`, marking them `to`.
  auto walk = [&](int start, uint8_t from, uint8_t to, auto visit) {
    WalkPiece<uint8_t>(start, from, to, cols, rows, cell, visit);
  };
  for (int start = 0; start < cols * rows; ++start) {
    if (cell[start] != kCore) continue;
    int64_t size = 0;
    bool reached = false;
    walk(start, kCore, kSeen, [&](int p) {
      ++size;
      reached = reached || label[p] > 0;
    });
    if (reached || size < min_core_cells) continue;
    walk(start, kSeen, kDone, [&](int p) {
      if (label[p] == 0) label[p] = kUnreached;
    });
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

AreaRaster PartitionFreeSpace(const CellGrid& grid, cv::Mat boundary_mask,
                              const std::vector<std::vector<const proto::Polygon*>>& area_polygons,
                              const std::vector<std::vector<PointList>>& area_paths,
                              const std::vector<std::pair<PointList, int>>& through_paths,
                              double min_gap_px, const cv::Mat& keep_out) {
  const cv::Size size(grid.width(), grid.height());
  CV_Assert(boundary_mask.size() == size && boundary_mask.type() == CV_8U);
  // The boundary mask's buffer becomes the domain (the caller hands it over).
  cv::Mat domain = boundary_mask.isContinuous() ? boundary_mask : boundary_mask.clone();
  boundary_mask.release();
  AreaRaster raster;
  const bool keeps_out = !keep_out.empty();
  for (int r = 0; r < size.height; ++r) {
    uint8_t* row = domain.ptr<uint8_t>(r);
    const uint8_t* out = keeps_out ? keep_out.ptr<uint8_t>(r) : nullptr;
    const uint8_t* state = grid.CellRow(r);
    for (int c = 0; c < size.width; ++c) {
      const bool kept_out = keeps_out && out[c] != 0;
      row[c] = row[c] && state[c] == proto::CELL_FREE && !kept_out ? 1 : 0;
      raster.domain_cells += row[c];
    }
  }
  cv::Mat core;
  if (min_gap_px > 0) core = CoreCells(grid, domain, min_gap_px);
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
  int* label = raster.labels.ptr<int>();
  const uint8_t* inside = domain.ptr<uint8_t>();
  const size_t cells = static_cast<size_t>(size.area());
  for (size_t i = 0; i < cells; ++i) {
    if (!inside[i]) label[i] = 0;
  }
  if (!core.empty()) MarkUnreachedCores(std::move(core), min_gap_px, &raster.labels);
  GrowLabels(domain, &raster.labels);
  KeepMainPieces(on_path, &raster.labels, static_cast<int>(area_polygons.size()));
  on_path.release();
  GrowLabels(domain, &raster.labels);
  for (size_t i = 0; i < cells; ++i) {
    if (label[i] == kUnreached) label[i] = 0;
  }
  raster.cell_count.assign(area_polygons.size(), 0);
  CountCells(&raster);
  return raster;
}

std::vector<cv::Rect> AreaBoxes(const AreaRaster& raster) {
  const int count = static_cast<int>(raster.cell_count.size());
  // Label k + 1 is area k; 0 and below are no area.
  const cv::Mat stats = LabelBoxes(raster.labels, count + 1);
  std::vector<cv::Rect> box(count);
  for (int k = 0; k < count; ++k) {
    const int* s = stats.ptr<int>(k + 1);
    if (s[cv::CC_STAT_AREA] > 0) {
      box[k] = cv::Rect(s[cv::CC_STAT_LEFT], s[cv::CC_STAT_TOP], s[cv::CC_STAT_WIDTH],
                        s[cv::CC_STAT_HEIGHT]);
    }
  }
  return box;
}

}  // namespace areagraph

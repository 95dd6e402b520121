#include "stages/merge/area_raster.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <opencv2/imgproc.hpp>

#include "stages/geometry/parallel_zeros.h"
#include "stages/geometry/polygon_raster.h"
#include "stages/geometry/region_boxes.h"
#include "stages/merge/core_cells.h"
#include "stages/merge/label_growth.h"
#include "stages/merge/path_cells.h"

namespace areagraph {
namespace {

// Label of the cells that free space the graph never reached claims while
// growing; cleared to 0 afterwards.
constexpr int kUnreached = -1;

// Clears every cell that is not in the main 4-connected piece of its label:
// the piece with most of the area's path cells (`on_path`), else the biggest
// (ties to the piece that a row-major scan meets first). Returns the runs cleared.
std::vector<PieceRun> KeepMainPieces(const cv::Mat& on_path, cv::Mat* labels, int label_count) {
  std::vector<PieceRun> runs;
  std::vector<int> piece_of_run;
  const int count = RunPieces(*labels, &runs, &piece_of_run);
  struct Piece {
    int label = 0;
    int64_t size = 0;
    int64_t path = 0;
  };
  std::vector<Piece> pieces(count);
  for (size_t i = 0; i < runs.size(); ++i) {
    const PieceRun& run = runs[i];
    Piece& piece = pieces[piece_of_run[i]];
    piece.label = run.value;
    piece.size += run.end - run.begin;
    const uint8_t* path = on_path.ptr<uint8_t>(run.row);
    for (int c = run.begin; c < run.end; ++c) piece.path += path[c] != 0;
  }
  std::vector<int> biggest(label_count + 1, -1);
  for (int id = 0; id < count; ++id) {
    const Piece& piece = pieces[id];
    int& best = biggest[piece.label];
    if (best < 0 || piece.path > pieces[best].path ||
        (piece.path == pieces[best].path && piece.size > pieces[best].size)) {
      best = id;
    }
  }
  std::vector<PieceRun> cleared;
  for (size_t i = 0; i < runs.size(); ++i) {
    const PieceRun& run = runs[i];
    if (biggest[run.value] == piece_of_run[i]) continue;
    int* row = labels->ptr<int>(run.row);
    std::fill(row + run.begin, row + run.end, 0);
    cleared.push_back(run);
  }
  return cleared;
}

// Marks kUnreached on the unlabelled cells of the cores (`core`, see
// CoreCells) whose 4-connected pieces no area's polygons or paths reach and
// that are big enough to be a room.
void MarkUnreachedCores(const cv::Mat& core, double min_gap_px, cv::Mat* labels) {
  // Pockets in clutter are no room: a core must span (2 gaps)^2 to stay unreached.
  const double min_core_cells = 4 * min_gap_px * min_gap_px;
  std::vector<PieceRun> runs;
  std::vector<int> piece_of_run;
  const int count = RunPieces(core, &runs, &piece_of_run);
  std::vector<int64_t> size(count, 0);
  std::vector<uint8_t> reached(count, 0);
  for (size_t i = 0; i < runs.size(); ++i) {
    const PieceRun& run = runs[i];
    const int piece = piece_of_run[i];
    size[piece] += run.end - run.begin;
    const int* row = labels->ptr<int>(run.row);
    for (int c = run.begin; c < run.end && !reached[piece]; ++c) reached[piece] = row[c] > 0;
  }
  for (size_t i = 0; i < runs.size(); ++i) {
    const PieceRun& run = runs[i];
    const int piece = piece_of_run[i];
    if (reached[piece] || size[piece] < min_core_cells) continue;
    int* row = labels->ptr<int>(run.row);
    for (int c = run.begin; c < run.end; ++c) {
      if (row[c] == 0) row[c] = kUnreached;
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
    uint8_t* __restrict row = domain.ptr<uint8_t>(r);
    const uint8_t* __restrict state = grid.CellRow(r);
    // Loops without a branch inside, which the compiler vectorises.
    if (keeps_out) {
      const uint8_t* __restrict out = keep_out.ptr<uint8_t>(r);
      for (int c = 0; c < size.width; ++c) {
        row[c] = (row[c] != 0) & (state[c] == proto::CELL_FREE) & (out[c] == 0);
      }
    } else {
      for (int c = 0; c < size.width; ++c) {
        row[c] = (row[c] != 0) & (state[c] == proto::CELL_FREE);
      }
    }
    int64_t count = 0;
    for (int c = 0; c < size.width; ++c) count += row[c];
    raster.domain_cells += count;
  }
  cv::Mat core;
  if (min_gap_px > 0) core = CoreCells(grid, domain, min_gap_px);
  std::vector<std::pair<const proto::Polygon*, int>> polygons;
  for (size_t k = 0; k < area_polygons.size(); ++k) {
    for (const proto::Polygon* polygon : area_polygons[k]) {
      polygons.emplace_back(polygon, static_cast<int>(k) + 1);
    }
  }
  raster.labels = PolygonLabels(polygons, size);
  cv::Mat on_path = ZerosInParallel(size, CV_8U);
  // 4-connected, so that an area's paths hold its pieces together.
  auto draw_path = [&](const PointList& path, int area) {
    PaintPathCells(path, area + 1, &raster.labels, &on_path);
  };
  for (size_t k = 0; k < area_paths.size(); ++k) {
    for (const PointList& path : area_paths[k]) draw_path(path, static_cast<int>(k));
  }
  for (const auto& [path, area] : through_paths) draw_path(path, area);
  int* label = raster.labels.ptr<int>();
  const uint8_t* inside = domain.ptr<uint8_t>();
  const size_t cells = static_cast<size_t>(size.area());
  for (size_t i = 0; i < cells; ++i) label[i] = inside[i] ? label[i] : 0;
  if (!core.empty()) MarkUnreachedCores(core, min_gap_px, &raster.labels);
  core.release();
  GrowLabels(domain, &raster.labels);
  const std::vector<PieceRun> cleared =
      KeepMainPieces(on_path, &raster.labels, static_cast<int>(area_polygons.size()));
  on_path.release();
  GrowIntoCleared(cleared, domain, &raster.labels);
  for (size_t i = 0; i < cells; ++i) label[i] = label[i] == kUnreached ? 0 : label[i];
  raster.cell_count.assign(area_polygons.size(), 0);
  CountAreaCells(&raster);
  return raster;
}

void CountAreaCells(AreaRaster* raster) {
  const int count = static_cast<int>(raster->cell_count.size());
  // Label k + 1 is area k; 0 and below are no area.
  const cv::Mat stats = LabelBoxes(raster->labels, count + 1);
  raster->boxes.assign(count, cv::Rect());
  for (int k = 0; k < count; ++k) {
    const int* s = stats.ptr<int>(k + 1);
    raster->cell_count[k] = s[cv::CC_STAT_AREA];
    if (s[cv::CC_STAT_AREA] > 0) {
      raster->boxes[k] = cv::Rect(s[cv::CC_STAT_LEFT], s[cv::CC_STAT_TOP], s[cv::CC_STAT_WIDTH],
                                  s[cv::CC_STAT_HEIGHT]);
    }
  }
}

}  // namespace areagraph

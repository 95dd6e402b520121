#include "stages/merge/closed_rooms.h"

#include <algorithm>
#include <opencv2/imgproc.hpp>
#include <set>

#include "stages/merge/vertex_openings.h"

namespace areagraph {
namespace {

constexpr int kDx[4] = {1, -1, 0, 0};
constexpr int kDy[4] = {0, 0, 1, -1};

// Twice the largest distance (px) from a cell of `area` (labels hold area + 1)
// to a cell outside it, inside `box`: the diameter of its largest inscribed disk.
double WidestInnerWidthPx(const cv::Mat& labels, int area, const cv::Rect& box) {
  const cv::Rect padded(box.x - 1, box.y - 1, box.width + 2, box.height + 2);
  cv::Mat mask = cv::Mat::zeros(padded.size(), CV_8U);
  for (int r = box.y; r < box.br().y; ++r) {
    const int* row = labels.ptr<int>(r);
    for (int c = box.x; c < box.br().x; ++c) {
      if (row[c] == area + 1) mask.at<uint8_t>(r - padded.y, c - padded.x) = 255;
    }
  }
  cv::Mat distance;
  cv::distanceTransform(mask, distance, cv::DIST_L2, cv::DIST_MASK_PRECISE);
  double largest = 0;
  cv::minMaxLoc(distance, nullptr, &largest);
  return 2 * largest;
}

// Whether at most kClosedRoomMaxUnknownShare of the faces between the cells
// of `area` and non-free cells face unknown ones.
bool WallsSeen(const cv::Mat& labels, const CellGrid& grid, int area, const cv::Rect& box) {
  int64_t non_free = 0, unknown = 0;
  for (int r = box.y; r < box.br().y; ++r) {
    const int* row = labels.ptr<int>(r);
    for (int c = box.x; c < box.br().x; ++c) {
      if (row[c] != area + 1) continue;
      for (int k = 0; k < 4; ++k) {
        const int x = c + kDx[k], y = r + kDy[k];
        const bool inside = grid.Contains(x, y);
        if (inside && grid.At(x, y) == proto::CELL_FREE) continue;
        ++non_free;
        if (!inside || grid.At(x, y) == proto::CELL_UNKNOWN) ++unknown;
      }
    }
  }
  return unknown <= kClosedRoomMaxUnknownShare * non_free;
}

}  // namespace

std::vector<bool> SmallClosedRooms(const proto::CutGraph& graph, const AreaPlan& plan,
                                   const AreaRaster& raster, const CellGrid& grid,
                                   int64_t min_cells) {
  const int area_count = static_cast<int>(plan.areas.size());
  std::vector<bool> kept(area_count, false);
  std::vector<std::set<int>> areas_at(graph.vertices_size());
  for (int e = 0; e < graph.edges_size(); ++e) {
    areas_at[graph.edges(e).source()].insert(plan.area_of_edge[e]);
    areas_at[graph.edges(e).target()].insert(plan.area_of_edge[e]);
  }
  // The vertices where each area meets another, and how many others meet it there.
  std::vector<std::vector<int>> shared(area_count);
  std::vector<int> others_at_shared(area_count, 0);
  for (int v = 0; v < graph.vertices_size(); ++v) {
    if (areas_at[v].size() < 2) continue;
    for (int k : areas_at[v]) {
      if (k < 0) continue;
      shared[k].push_back(v);
      others_at_shared[k] = static_cast<int>(areas_at[v].size()) - 1;
    }
  }
  const std::vector<bool> closed = ClosedVertices(graph, /*keep_closed_doors=*/true);
  const std::vector<std::map<int, VertexOpening>> openings = OpeningsAtVertices(graph, plan);
  const std::vector<cv::Rect> boxes = AreaBoxes(raster);
  for (int k = 0; k < area_count; ++k) {
    const int64_t cells = raster.cell_count[k];
    if (cells == 0 || cells >= min_cells || shared[k].size() != 1 || others_at_shared[k] != 1) {
      continue;
    }
    const int v = shared[k].front();
    if (!closed[v]) continue;
    const auto own = openings[v].find(k);
    if (own == openings[v].end()) continue;
    if (own->second.width_px >=
        kClosedRoomOpeningShare * WidestInnerWidthPx(raster.labels, k, boxes[k])) {
      continue;
    }
    kept[k] = WallsSeen(raster.labels, grid, k, boxes[k]);
  }
  return kept;
}

}  // namespace areagraph

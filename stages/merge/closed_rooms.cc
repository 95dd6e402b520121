#include "stages/merge/closed_rooms.h"

#include <algorithm>
#include <set>

#include "stages/geometry/distance_transform.h"
#include "stages/geometry/region_boxes.h"
#include "stages/merge/vertex_openings.h"

namespace areagraph {
namespace {

constexpr int kDx[4] = {1, -1, 0, 0};
constexpr int kDy[4] = {0, 0, 1, -1};

// Twice the largest distance (px) from a cell of `area` to a cell outside it,
// inside `box`: the diameter of its largest inscribed disk.
double WidestInnerWidthPx(const AreaRaster& raster, int area, const cv::Rect& box) {
  return 2 * DeepestDistance(LabelMaskInBox(raster.labels, area + 1, box));
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
  const std::vector<std::set<int>> areas_at = AreasAtVertices(graph, plan);
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
  const std::vector<cv::Rect>& boxes = raster.boxes;
  for (int k = 0; k < area_count; ++k) {
    const int64_t cells = raster.cell_count[k];
    if (cells == 0 || cells >= min_cells || shared[k].size() != 1 || others_at_shared[k] != 1) {
      continue;
    }
    const int v = shared[k].front();
    if (!closed[v]) continue;
    const auto own = openings[v].find(k);
    if (own == openings[v].end()) continue;
    if (own->second.width_px >= kClosedRoomOpeningShare * WidestInnerWidthPx(raster, k, boxes[k])) {
      continue;
    }
    kept[k] = WallsSeen(raster.labels, grid, k, boxes[k]);
  }
  return kept;
}

}  // namespace areagraph

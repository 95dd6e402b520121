#include "stages/merge/closed_rooms.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>

#include "stages/geometry/distance_transform.h"
#include "stages/geometry/region_boxes.h"
#include "stages/geometry/wall_thickness.h"
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

// Whether at most kMissedWallShare of the faces between the cells
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
  return unknown <= kMissedWallShare * non_free;
}

// Thickness (m) of the obstacle behind `jamb`, seen from the other jamb
// `from`: the run of non-free cells through the point kJambDepthM beyond the
// jamb on their line, across that line, between free cells on both sides;
// infinity when either side meets no free cell within `enough_m` (the run is
// then at least that thick: the search stops there).
double JambThicknessM(const CellGrid& grid, const Eigen::Vector2d& from,
                      const Eigen::Vector2d& jamb, double enough_m) {
  const double res = grid.resolution_m();
  const Eigen::Vector2d along = (jamb - from).normalized();
  const Eigen::Vector2d across(-along.y(), along.x());
  const Eigen::Vector2d point = jamb + along * (kJambDepthM / res);
  const int limit = static_cast<int>(std::ceil(enough_m / res));
  int run = 0;
  for (const double sign : {1.0, -1.0}) {
    for (int step = 0;; ++step) {
      const Eigen::Vector2d p = point + sign * step * across;
      const int x = static_cast<int>(std::lround(p.x())), y = static_cast<int>(std::lround(p.y()));
      if (step > limit || !grid.Contains(x, y)) return std::numeric_limits<double>::infinity();
      if (grid.At(x, y) == proto::CELL_FREE) {
        run += step;
        break;
      }
    }
  }
  return std::max(0, run - 1) * res;
}

}  // namespace

std::vector<bool> SmallClosedRooms(const proto::CutGraph& graph, const AreaPlan& plan,
                                   const AreaRaster& raster, const CellGrid& grid,
                                   const std::vector<bool>& closed, int64_t min_cells,
                                   double pocket_jamb_m) {
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
    if (own->second.width_px >= (1 - kSameWidthShare) * WidestInnerWidthPx(raster, k, boxes[k])) {
      continue;
    }
    if (pocket_jamb_m > 0 &&
        JambThicknessM(grid, own->second.right, own->second.left, pocket_jamb_m) >= pocket_jamb_m &&
        JambThicknessM(grid, own->second.left, own->second.right, pocket_jamb_m) >= pocket_jamb_m) {
      continue;  // a pocket between furniture, not a door in a wall
    }
    kept[k] = WallsSeen(raster.labels, grid, k, boxes[k]);
  }
  return kept;
}

}  // namespace areagraph

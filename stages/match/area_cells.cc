#include "stages/match/area_cells.h"

#include <algorithm>
#include <cmath>
#include <map>

#include "stages/common/map_frame.h"

namespace areagraph {
namespace {

// Where a polygon's edges cross the centre lines of rows, for one area.
class RowCrossings {
 public:
  RowCrossings(int first_row, int rows)
      : first_row_(first_row), rows_(rows), crossings_(static_cast<size_t>(rows)) {}

  // Adds the crossings of edge a-b (pixel coordinates) with the lines
  // y = r + 0.5; an edge owns its lower end point and not its upper one.
  void AddEdge(const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
    if (a.y() == b.y()) return;
    const double y_min = std::min(a.y(), b.y()), y_max = std::max(a.y(), b.y());
    // Rows whose centre y satisfies y_min <= y < y_max.
    const int r0 = std::max(first_row_, static_cast<int>(std::ceil(y_min - 0.5)));
    const int r1 = std::min(first_row_ + rows_, static_cast<int>(std::ceil(y_max - 0.5)));
    const double slope = (b.x() - a.x()) / (b.y() - a.y());
    for (int r = r0; r < r1; ++r) {
      crossings_[r - first_row_].push_back(a.x() + (r + 0.5 - a.y()) * slope);
    }
  }

  // Turns the crossings into runs of `area` (even-odd pairs, cells whose
  // centre x lies in [left, right)), clipped to [0, width).
  void EmitRuns(int area, int width, std::vector<std::vector<CellRun>>& rows) {
    for (int i = 0; i < rows_; ++i) {
      std::vector<double>& xs = crossings_[i];
      std::sort(xs.begin(), xs.end());
      for (size_t k = 0; k + 1 < xs.size(); k += 2) {
        const int x0 = std::max(0, static_cast<int>(std::ceil(xs[k] - 0.5)));
        const int x1 = std::min(width, static_cast<int>(std::ceil(xs[k + 1] - 0.5)));
        if (x1 > x0) rows[first_row_ + i].push_back({x0, x1, area});
      }
    }
  }

 private:
  int first_row_;
  int rows_;
  std::vector<std::vector<double>> crossings_;  // per row from first_row_
};

std::vector<Eigen::Vector2d> ToPixels(const proto::Ring& ring, const MapTransform& transform) {
  std::vector<Eigen::Vector2d> points;
  points.reserve(ring.points_size());
  for (const proto::Point2& point : ring.points()) {
    points.push_back(transform.WorldToPixel({point.x(), point.y()}));
  }
  return points;
}

// Sorts a row's runs and cuts away what overlaps an earlier run.
void MakeDisjoint(std::vector<CellRun>& runs) {
  std::sort(runs.begin(), runs.end(), [](const CellRun& a, const CellRun& b) {
    return a.x0 != b.x0 ? a.x0 < b.x0 : a.area < b.area;
  });
  std::vector<CellRun> kept;
  int end = 0;
  for (CellRun run : runs) {
    run.x0 = std::max(run.x0, end);
    if (run.x1 <= run.x0) continue;
    end = run.x1;
    kept.push_back(run);
  }
  runs.swap(kept);
}

}  // namespace

AreaCells RasterizeAreas(const proto::AreaGraph& graph, const proto::MapFrame& frame) {
  AreaCells cells;
  cells.width = std::max(0, frame.width_px());
  cells.height = std::max(0, frame.height_px());
  cells.resolution_m = frame.resolution_m();
  cells.rows.resize(cells.height);
  cells.cells.assign(graph.areas_size(), 0);
  const MapTransform transform(frame);
  for (int k = 0; k < graph.areas_size(); ++k) {
    const proto::Polygon& polygon = graph.areas(k).polygon_m();
    std::vector<std::vector<Eigen::Vector2d>> rings = {ToPixels(polygon.outer(), transform)};
    for (const proto::Ring& hole : polygon.holes()) rings.push_back(ToPixels(hole, transform));
    double y_min = INFINITY, y_max = -INFINITY;
    for (const auto& ring : rings) {
      for (const Eigen::Vector2d& point : ring) {
        y_min = std::min(y_min, point.y());
        y_max = std::max(y_max, point.y());
      }
    }
    if (rings[0].size() < 3 || !std::isfinite(y_min) || !std::isfinite(y_max)) continue;
    const int first_row = std::max(0, static_cast<int>(std::floor(y_min)));
    const int end_row = std::min(cells.height, static_cast<int>(std::ceil(y_max)) + 1);
    if (end_row <= first_row) continue;
    RowCrossings crossings(first_row, end_row - first_row);
    for (const auto& ring : rings) {
      for (size_t i = 0; i < ring.size(); ++i) {
        crossings.AddEdge(ring[i], ring[(i + 1) % ring.size()]);
      }
    }
    crossings.EmitRuns(k, cells.width, cells.rows);
  }
  for (std::vector<CellRun>& runs : cells.rows) {
    MakeDisjoint(runs);
    for (const CellRun& run : runs) cells.cells[run.area] += run.x1 - run.x0;
  }
  return cells;
}

std::vector<AreaOverlap> CountOverlaps(const AreaCells& before, const AreaCells& after) {
  std::map<std::pair<int, int>, int64_t> shared;
  const int rows = std::min(before.rows.size(), after.rows.size());
  for (int r = 0; r < rows; ++r) {
    const std::vector<CellRun>& a = before.rows[r];
    const std::vector<CellRun>& b = after.rows[r];
    size_t i = 0, j = 0;
    while (i < a.size() && j < b.size()) {
      const int overlap = std::min(a[i].x1, b[j].x1) - std::max(a[i].x0, b[j].x0);
      if (overlap > 0) shared[{a[i].area, b[j].area}] += overlap;
      if (a[i].x1 < b[j].x1) {
        ++i;
      } else {
        ++j;
      }
    }
  }
  std::vector<AreaOverlap> overlaps;
  overlaps.reserve(shared.size());
  for (const auto& [pair, count] : shared) overlaps.push_back({pair.first, pair.second, count});
  return overlaps;
}

}  // namespace areagraph

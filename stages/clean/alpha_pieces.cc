#include "stages/clean/alpha_pieces.h"

#include <Eigen/Core>
#include <algorithm>
#include <cfloat>
#include <cmath>

#include "stages/geometry/alpha_shape.h"
#include "stages/geometry/cell_states.h"
#include "stages/geometry/disjoint_sets.h"
#include "stages/geometry/parallel_ranges.h"

namespace areagraph {
namespace {

std::vector<Eigen::Vector2d> CellCentres(const std::vector<int>& cells, int width) {
  std::vector<Eigen::Vector2d> points;
  points.reserve(cells.size());
  for (const int index : cells) points.push_back(CellCentre(index % width, index / width));
  return points;
}

// Numbers the furniture pieces by their first point: per point the number
// of its piece when furniture[piece_of_point[p]], else -1 (so also for
// points with no piece, -1).
FurniturePieces NumberFurniture(const std::vector<int>& piece_of_point,
                                const std::vector<uint8_t>& furniture) {
  FurniturePieces result;
  result.piece_of_point.assign(piece_of_point.size(), -1);
  std::vector<int> number(furniture.size(), -1);
  for (size_t p = 0; p < piece_of_point.size(); ++p) {
    const int piece = piece_of_point[p];
    if (piece < 0 || !furniture[piece]) continue;
    if (number[piece] < 0) number[piece] = result.count++;
    result.piece_of_point[p] = number[piece];
  }
  return result;
}

// A point cluster's alpha shape: per point its component, and per component
// the perimeter as ComponentPerimeters sums it, the number of terms summed
// and whether every term is an integer (then any order sums it exactly).
struct ClusterShape {
  std::vector<int> component_of_point;
  std::vector<double> perimeter;
  std::vector<int> terms;
  std::vector<uint8_t> integral;
};

ClusterShape ShapeOfCluster(const std::vector<int>& cells, int width, double alpha_radius_px) {
  const std::vector<Eigen::Vector2d> points = CellCentres(cells, width);
  AlphaComplex complex = ComputeAlphaComplex(points, alpha_radius_px);
  ClusterShape shape;
  shape.perimeter.assign(complex.component_count, 0.0);
  shape.terms.assign(complex.component_count, 0);
  shape.integral.assign(complex.component_count, 1);
  for (const AlphaShapeEdge& edge : complex.boundary_edges) {
    const double length = (points[edge.b] - points[edge.a]).norm();
    const int component = complex.component_of_point[edge.a];
    shape.perimeter[component] += edge.singular ? 2 * length : length;
    shape.terms[component] += 1;
    shape.integral[component] &= length == std::floor(length);
  }
  shape.component_of_point = std::move(complex.component_of_point);
  return shape;
}

// A run of point cells in one row: columns [begin, end), points first ...
struct PointRun {
  int row;
  int begin;
  int end;
  int first;
};

// Enough points for two threads to pay (a cluster's triangulation costs
// some microseconds per point).
constexpr size_t kParallelPoints = 1500;

}  // namespace

FurniturePieces FurniturePiecesOfWholeShape(const std::vector<int>& point_cells, int width,
                                            const int* label, const std::vector<uint8_t>& outline,
                                            double alpha_radius_px, double max_perimeter_px) {
  const std::vector<Eigen::Vector2d> points = CellCentres(point_cells, width);
  // Pieces: alpha-shape components joined through shared obstacle regions.
  const AlphaComplex complex = ComputeAlphaComplex(points, alpha_radius_px);
  const std::vector<double> component_perimeters = ComponentPerimeters(points, complex);
  DisjointSets pieces(complex.component_count);
  std::vector<int> component_of_region(outline.size(), -1);
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
  std::vector<uint8_t> furniture(piece_count, 1);
  for (int piece = 0; piece < piece_count; ++piece) {
    furniture[piece] = perimeter[piece] < max_perimeter_px;
  }
  for (size_t region = 1; region < outline.size(); ++region) {
    if (outline[region] && component_of_region[region] >= 0) {
      furniture[piece_of_component[component_of_region[region]]] = 0;
    }
  }
  std::vector<int> piece_of_point(points.size());
  for (size_t p = 0; p < points.size(); ++p) {
    piece_of_point[p] = piece_of_component[complex.component_of_point[p]];
  }
  return NumberFurniture(piece_of_point, furniture);
}

// Why the clusters give the whole shape's pieces (disk radius R, alpha =
// R^2; squared distances of cell centres are exact integers):
// - A complex edge is a Delaunay edge no longer than 2R (up to the rounding
//   of a face's circumradius), so points in different "loose" clusters
//   (joined below 4 alpha (1 + 1e-9)) never share a component; and a disk
//   of radius <= R through two points of a cluster holds no point of
//   another, so each cluster's own triangulation has the same interior
//   faces, singular edges (the diametral test is exact) and components.
// - Points closer than 2R (1 - 1e-9) ("strict" clusters) always share a
//   component: the exact complex at their half distance joins them, and
//   the rounded one at alpha holds it. So when every strict cluster of a
//   loose one holds a point of an outline region, every component of it
//   belongs to an outline piece: nothing there can be furniture.
// - An obstacle region's cells are 8-connected, closer than 2R for R >= 1:
//   a region lies in one strict cluster.
// - The perimeters are the same terms summed in another order: either all
//   integers (exact in any order) or, far enough from the bound, on the
//   same side whatever the order (a sum of n positive terms is within
//   (n - 1) u of its true value relatively, in any order).
bool FurniturePiecesByClusters(const std::vector<int>& point_cells, int width, int height,
                               const int* label, const std::vector<uint8_t>& outline,
                               double alpha_radius_px, double max_perimeter_px,
                               FurniturePieces* result) {
  if (!(alpha_radius_px >= 1) || !std::isfinite(alpha_radius_px)) return false;
  const double alpha = alpha_radius_px * alpha_radius_px;
  const double loose = 4 * alpha * (1 + 1e-9);
  const double strict = 4 * alpha * (1 - 1e-9);

  // The points' runs; a run's cells are one region's (neighbours are).
  std::vector<PointRun> runs;
  std::vector<int> row_start(size_t(height) + 1, 0);
  for (size_t p = 0; p < point_cells.size(); ++p) {
    const int row = point_cells[p] / width;
    const int col = point_cells[p] % width;
    if (!runs.empty() && runs.back().row == row && runs.back().end == col) {
      ++runs.back().end;
    } else {
      runs.push_back({row, col, col + 1, int(p)});
      ++row_start[row + 1];
    }
  }
  for (int row = 0; row < height; ++row) row_start[row + 1] += row_start[row];

  // Runs join when their nearest cells are close enough.
  DisjointSets loose_sets(runs.size()), strict_sets(runs.size());
  const int reach = int(std::floor(std::sqrt(loose)));
  for (size_t i = 0; i < runs.size(); ++i) {
    const PointRun& a = runs[i];
    for (int dr = 0; dr <= reach && a.row + dr < height; ++dr) {
      const long dr2 = long(dr) * dr;
      const int span = int(std::floor(std::sqrt(loose - double(dr2))));
      const auto row_end = runs.begin() + row_start[a.row + dr + 1];
      auto b = dr == 0 ? runs.begin() + long(i) + 1
                       : std::lower_bound(
                             runs.begin() + row_start[a.row + dr], row_end, a.begin - span,
                             [](const PointRun& run, int col) { return run.end - 1 < col; });
      for (; b != row_end && b->begin <= a.end - 1 + span; ++b) {
        const long gap = std::max({0, b->begin - (a.end - 1), a.begin - (b->end - 1)});
        const double d2 = double(gap * gap + dr2);
        const int j = int(b - runs.begin());
        if (d2 <= loose) loose_sets.Union(int(i), j);
        if (d2 < strict) strict_sets.Union(int(i), j);
      }
    }
  }
  int loose_count = 0, strict_count = 0;
  const std::vector<int> loose_of_run = loose_sets.DenseLabels(&loose_count);
  const std::vector<int> strict_of_run = strict_sets.DenseLabels(&strict_count);
  std::vector<uint8_t> strict_outline(strict_count, 0);
  for (size_t i = 0; i < runs.size(); ++i) {
    const int row_offset = runs[i].row * width;
    for (int col = runs[i].begin; col < runs[i].end; ++col) {
      strict_outline[strict_of_run[i]] |= outline[label[row_offset + col]];
    }
  }
  // A loose cluster is triangulated when one of its strict clusters has no
  // outline point; its points in order.
  std::vector<uint8_t> needed(loose_count, 0);
  for (size_t i = 0; i < runs.size(); ++i)
    needed[loose_of_run[i]] |= !strict_outline[strict_of_run[i]];
  std::vector<int> slot(loose_count, -1);
  std::vector<std::vector<int>> cluster_points;
  size_t needed_points = 0;
  for (size_t i = 0; i < runs.size(); ++i) {
    if (!needed[loose_of_run[i]]) continue;
    int& s = slot[loose_of_run[i]];
    if (s < 0) {
      s = int(cluster_points.size());
      cluster_points.emplace_back();
    }
    for (int p = runs[i].first; p < runs[i].first + (runs[i].end - runs[i].begin); ++p) {
      cluster_points[s].push_back(p);
    }
    needed_points += runs[i].end - runs[i].begin;
  }

  // Each cluster's shape in its own slot: no order depends on the threads.
  std::vector<ClusterShape> shapes(cluster_points.size());
  const int ranges =
      needed_points >= kParallelPoints ? ParallelRangeCount(cluster_points.size(), 1) : 1;
  ForEachRange(cluster_points.size(), ranges, [&](size_t begin, size_t end, int) {
    std::vector<int> cells;
    for (size_t s = begin; s < end; ++s) {
      cells.clear();
      for (const int p : cluster_points[s]) cells.push_back(point_cells[p]);
      shapes[s] = ShapeOfCluster(cells, width, alpha_radius_px);
    }
  });

  // Components numbered cluster by cluster; pieces join them by region.
  std::vector<int> component_of_point(point_cells.size(), -1);
  std::vector<int> offset(shapes.size() + 1, 0);
  for (size_t s = 0; s < shapes.size(); ++s) {
    offset[s + 1] = offset[s] + int(shapes[s].perimeter.size());
    for (size_t k = 0; k < cluster_points[s].size(); ++k) {
      component_of_point[cluster_points[s][k]] = offset[s] + shapes[s].component_of_point[k];
    }
  }
  const int component_count = offset.back();
  DisjointSets pieces(component_count);
  std::vector<int> component_of_region(outline.size(), -1);
  for (size_t p = 0; p < point_cells.size(); ++p) {
    if (component_of_point[p] < 0) continue;
    int& first = component_of_region[label[point_cells[p]]];
    if (first < 0) first = component_of_point[p];
    pieces.Union(first, component_of_point[p]);
  }
  int piece_count = 0;
  const std::vector<int> piece_of_component = pieces.DenseLabels(&piece_count);
  std::vector<double> perimeter(piece_count, 0.0);
  std::vector<long> terms(piece_count, 0);
  std::vector<uint8_t> integral(piece_count, 1);
  for (size_t s = 0; s < shapes.size(); ++s) {
    for (size_t c = 0; c < shapes[s].perimeter.size(); ++c) {
      const int piece = piece_of_component[offset[s] + int(c)];
      perimeter[piece] += shapes[s].perimeter[c];
      terms[piece] += shapes[s].terms[c] + 1;
      integral[piece] &= shapes[s].integral[c];
    }
  }
  std::vector<uint8_t> furniture(piece_count, 1);
  for (size_t region = 1; region < outline.size(); ++region) {
    if (outline[region] && component_of_region[region] >= 0) {
      furniture[piece_of_component[component_of_region[region]]] = 0;
    }
  }
  for (int piece = 0; piece < piece_count; ++piece) {
    if (!furniture[piece]) continue;
    const double sum = perimeter[piece];
    if (!(integral[piece] && sum < 0x1p52)) {
      const double slack = 4.0 * double(terms[piece] + 1) * DBL_EPSILON * sum;
      if (!(std::abs(sum - max_perimeter_px) > slack)) return false;
    }
    furniture[piece] = sum < max_perimeter_px;
  }
  std::vector<int> piece_of_point(point_cells.size(), -1);
  for (size_t p = 0; p < point_cells.size(); ++p) {
    if (component_of_point[p] >= 0) piece_of_point[p] = piece_of_component[component_of_point[p]];
  }
  *result = NumberFurniture(piece_of_point, furniture);
  return true;
}

}  // namespace areagraph

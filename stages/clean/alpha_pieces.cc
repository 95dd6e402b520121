#include "stages/clean/alpha_pieces.h"

#include <Eigen/Core>
#include <algorithm>
#include <cfloat>
#include <cmath>
#include <limits>

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

// Per point its loose and strict cluster (see FurniturePiecesByClusters),
// numbered by first point.
struct PointClusters {
  std::vector<int> loose, strict;
  int loose_count = 0, strict_count = 0;
};

// Points in square buckets small enough that any two of one bucket are
// strictly close; buckets joined when two of their points are close enough
// (pairs tested only while the buckets are apart in either relation).
PointClusters ClusterPoints(const std::vector<int>& cells, int width, int height, double loose,
                            double strict) {
  long side = 1;  // bucket side - 1: its diagonal's square 2 side^2 < strict
  while (2.0 * double((side + 1) * (side + 1)) < strict) ++side;
  const int bucket = int(side) + 1;
  const int columns = (width + bucket - 1) / bucket, rows = (height + bucket - 1) / bucket;
  // Buckets whose nearest cells lie within the loose distance.
  const int reach = int(std::ceil(std::sqrt(loose))) / bucket + 1;
  std::vector<int> bucket_of(cells.size());
  std::vector<int> start(size_t(columns) * rows + 1, 0);
  for (size_t p = 0; p < cells.size(); ++p) {
    bucket_of[p] = (cells[p] / width / bucket) * columns + (cells[p] % width) / bucket;
    ++start[bucket_of[p] + 1];
  }
  for (size_t b = 0; b + 1 < start.size(); ++b) start[b + 1] += start[b];
  // Points bucket by bucket: their columns and rows, and each bucket's box.
  std::vector<int> col(cells.size()), row(cells.size());
  std::vector<int> box(4 * (start.size() - 1));  // min col, max col, min row, max row
  {
    std::vector<int> next(start.begin(), start.end() - 1);
    for (size_t p = 0; p < cells.size(); ++p) {
      const int b = bucket_of[p], at = next[b]++;
      col[at] = cells[p] % width;
      row[at] = cells[p] / width;
      int* bounds = &box[4 * size_t(b)];
      if (at == start[b]) {
        bounds[0] = bounds[1] = col[at];
        bounds[2] = bounds[3] = row[at];
      }
      bounds[0] = std::min(bounds[0], col[at]);
      bounds[1] = std::max(bounds[1], col[at]);
      bounds[3] = row[at];  // rows come in order
    }
  }
  DisjointSets loose_sets(size_t(columns) * rows), strict_sets(size_t(columns) * rows);
  for (int b = 0; b < columns * rows; ++b) {
    if (start[b] == start[b + 1]) continue;
    const int bx = b % columns, by = b / columns;
    const int* a_box = &box[4 * size_t(b)];
    for (int dy = 0; dy <= reach && by + dy < rows; ++dy) {
      for (int dx = dy == 0 ? 1 : -reach; dx <= reach; ++dx) {
        if (bx + dx < 0 || bx + dx >= columns) continue;
        const int o = b + dy * columns + dx;
        if (start[o] == start[o + 1]) continue;
        // The boxes' gap bounds every pair's distance from below.
        const int* o_box = &box[4 * size_t(o)];
        const long gap_c = std::max({0, o_box[0] - a_box[1], a_box[0] - o_box[1]});
        const long gap_r = std::max({0, o_box[2] - a_box[3], a_box[2] - o_box[3]});
        if (double(gap_c * gap_c + gap_r * gap_r) > loose) continue;
        const bool loose_apart = loose_sets.Find(b) != loose_sets.Find(o);
        const bool strict_apart = strict_sets.Find(b) != strict_sets.Find(o);
        if (!loose_apart && !strict_apart) continue;
        long nearest = std::numeric_limits<long>::max();
        for (int i = start[b]; i < start[b + 1] && double(nearest) >= strict; ++i) {
          for (int j = start[o]; j < start[o + 1]; ++j) {
            const long dc = col[j] - col[i], dr = row[j] - row[i];
            nearest = std::min(nearest, dc * dc + dr * dr);
          }
        }
        if (double(nearest) <= loose) loose_sets.Union(b, o);
        if (double(nearest) < strict) strict_sets.Union(b, o);
      }
    }
  }
  PointClusters clusters;
  clusters.loose.resize(cells.size());
  clusters.strict.resize(cells.size());
  std::vector<int> loose_number(size_t(columns) * rows, -1), strict_number(loose_number);
  for (size_t p = 0; p < cells.size(); ++p) {
    int& l = loose_number[loose_sets.Find(bucket_of[p])];
    if (l < 0) l = clusters.loose_count++;
    clusters.loose[p] = l;
    int& s = strict_number[strict_sets.Find(bucket_of[p])];
    if (s < 0) s = clusters.strict_count++;
    clusters.strict[p] = s;
  }
  return clusters;
}

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

  const PointClusters clusters = ClusterPoints(point_cells, width, height, loose, strict);
  std::vector<uint8_t> strict_outline(clusters.strict_count, 0);
  for (size_t p = 0; p < point_cells.size(); ++p) {
    strict_outline[clusters.strict[p]] |= outline[label[point_cells[p]]];
  }
  // A loose cluster is triangulated when one of its strict clusters has no
  // outline point; its points in order.
  std::vector<uint8_t> needed(clusters.loose_count, 0);
  for (size_t p = 0; p < point_cells.size(); ++p) {
    needed[clusters.loose[p]] |= !strict_outline[clusters.strict[p]];
  }
  std::vector<int> slot(clusters.loose_count, -1);
  std::vector<std::vector<int>> cluster_points;
  size_t needed_points = 0;
  for (size_t p = 0; p < point_cells.size(); ++p) {
    if (!needed[clusters.loose[p]]) continue;
    int& s = slot[clusters.loose[p]];
    if (s < 0) {
      s = int(cluster_points.size());
      cluster_points.emplace_back();
    }
    cluster_points[s].push_back(int(p));
    ++needed_points;
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

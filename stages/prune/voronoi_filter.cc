#include "stages/prune/voronoi_filter.h"

#include <set>
#include <string>
#include <utility>

#include "common/error.h"
#include "stages/common/voronoi_arrays.h"
#include "stages/geometry/disjoint_sets.h"
#include "stages/geometry/parallel_ranges.h"

namespace areagraph {
namespace {

// Voronoi vertices closer than this (pixels) are one vertex: grid maps have
// many co-circular sites, whose Voronoi vertices coincide.
constexpr double kSamePointPx = 1e-6;

// How many vertices (or edges) ahead the loops over the diagram ask for the
// memory they will read at random (__builtin_prefetch): on a big map the
// grid, the vertices' positions and their flags do not fit in the caches.
constexpr int kAhead = 16;

// Below this many Voronoi edges per range the filter runs in the calling
// thread.
constexpr size_t kMinEdgesPerFilterRange = 16384;
// Below this many entries per range the diagram's arrays are copied in the
// calling thread.
constexpr size_t kMinCopiesPerRange = 32768;

// Asks for the grid's cell under `point` (as CellGrid::FreeAt reads it).
inline void PrefetchCell(const CellGrid& grid, const Eigen::Vector2d& point) {
  if (point.x() >= 0 && point.y() >= 0 && point.x() < grid.width() && point.y() < grid.height()) {
    __builtin_prefetch(grid.CellRow(static_cast<int>(point.y())) + static_cast<int>(point.x()));
  }
}

[[noreturn]] __attribute__((noinline)) void ThrowBadIndex(int index, int size, const char* element,
                                                          int edge) {
  throw InputError("the Voronoi diagram artifact is corrupt: edge " + std::to_string(edge) +
                   " names " + element + " " + std::to_string(index) + " of " +
                   std::to_string(size));
}

// Throws when a Voronoi edge names a vertex or site that does not exist. The
// test inline, the message out of line: four calls per edge (520 000 on a cluttered scan).
inline void CheckIndex(int index, int size, const char* element, int edge) {
  if (index < 0 || index >= size) ThrowBadIndex(index, size, element, edge);
}

void CopyPoints(const double* x, const double* y, size_t count, PointList* out) {
  out->resize(count);  // Eigen's vectors stay unset
  Eigen::Vector2d* points = out->data();
  ForEachRange(count, ParallelRangeCount(count, kMinCopiesPerRange),
               [&](size_t begin, size_t end, int) {
                 for (size_t i = begin; i < end; ++i) points[i] = Eigen::Vector2d(x[i], y[i]);
               });
}

}  // namespace

PlainVoronoi::PlainVoronoi(const proto::VoronoiDiagram& diagram)
    : clearances(diagram.vertex_clearance_px().begin(), diagram.vertex_clearance_px().end()) {
  CopyPoints(diagram.site_x().data(), diagram.site_y().data(), diagram.site_x_size(), &sites);
  CopyPoints(diagram.vertex_x().data(), diagram.vertex_y().data(), diagram.vertex_x_size(),
             &positions);
  const int* source = diagram.edge_source().data();
  const int* target = diagram.edge_target().data();
  const int* left = diagram.edge_left_site().data();
  const int* right = diagram.edge_right_site().data();
  const double* clearance = diagram.edge_clearance_px().data();
  const size_t count = diagram.edge_source_size();
  edges.resize(count);
  ForEachRange(count, ParallelRangeCount(count, kMinCopiesPerRange),
               [&](size_t begin, size_t end, int) {
                 for (size_t e = begin; e < end; ++e) {
                   Edge& edge = edges[e];
                   edge.source = source[e];
                   edge.target = target[e];
                   edge.left_site = left[e];
                   edge.right_site = right[e];
                   edge.clearance_px = clearance[e];
                 }
               });
}

PlainVoronoi PlainVoronoiOf(const proto::VoronoiDiagram& diagram) {
  proto::VoronoiDiagram converted;
  return PlainVoronoi(PackedVoronoi(diagram, &converted));
}
FilteredGraph FilteredVoronoiGraph(const PlainVoronoi& diagram, const CellGrid& grid,
                                   std::unique_ptr<SiteAlphaShape> boundary_shape,
                                   double min_clearance_px) {
  const int vertex_count = static_cast<int>(diagram.positions.size());
  const int site_count = static_cast<int>(diagram.sites.size());
  // The region of every vertex on a free cell (over ranges of the vertices
  // in parallel; the grid is only read).
  const std::vector<int> region = boundary_shape->EnclosedRegionsAt(diagram.positions, [&](int v) {
    if (v + kAhead < vertex_count) PrefetchCell(grid, diagram.positions[v + kAhead]);
    return grid.FreeAt(diagram.positions[v]);
  });
  std::vector<char> keep(vertex_count, 0);
  for (int v = 0; v < vertex_count; ++v) keep[v] = region[v] >= 0;

  // The edges over ranges in parallel: each range keeps its edges and the
  // pairs of vertices at one point, in edge order, and stops at its first
  // bad index; the first range's error is thrown, as the serial loop would.
  struct RangeEdges {
    std::vector<int> kept;
    std::vector<std::pair<int, int>> same;
    int bad_edge = -1;  // the first edge naming a missing vertex or site
  };
  const int edge_count = static_cast<int>(diagram.edges.size());
  const auto ranges =
      MapRanges<RangeEdges>(edge_count, kMinEdgesPerFilterRange, [&](size_t begin, size_t end) {
        RangeEdges out;
        auto bad = [](int index, int size) { return index < 0 || index >= size; };
        for (size_t e = begin; e < end; ++e) {
          if (e + kAhead < end) {
            const PlainVoronoi::Edge& ahead = diagram.edges[e + kAhead];
            for (const int v : {ahead.source, ahead.target}) {
              if (v >= 0 && v < vertex_count) {
                __builtin_prefetch(&keep[v]);
                __builtin_prefetch(&diagram.positions[v]);
              }
            }
          }
          const PlainVoronoi::Edge& edge = diagram.edges[e];
          if (bad(edge.source, vertex_count) ||
              (edge.target >= 0 &&
               (bad(edge.target, vertex_count) || bad(edge.left_site, site_count) ||
                bad(edge.right_site, site_count)))) {
            out.bad_edge = static_cast<int>(e);
            break;
          }
          if (edge.target < 0) continue;  // a ray
          if (!keep[edge.source] || !keep[edge.target]) continue;
          if (!(edge.clearance_px >= min_clearance_px)) continue;
          const Eigen::Vector2d& a = diagram.positions[edge.source];
          const Eigen::Vector2d& b = diagram.positions[edge.target];
          if ((a - b).norm() < kSamePointPx) {
            out.same.emplace_back(edge.source, edge.target);
          } else {
            out.kept.push_back(static_cast<int>(e));
          }
        }
        return out;
      });
  DisjointSets same_point(vertex_count);
  std::vector<int> kept_edges;
  for (const RangeEdges& range : ranges) {
    if (range.bad_edge >= 0) {
      const int e = range.bad_edge;
      const PlainVoronoi::Edge& edge = diagram.edges[e];
      CheckIndex(edge.source, vertex_count, "vertex", e);
      CheckIndex(edge.target, vertex_count, "vertex", e);
      CheckIndex(edge.left_site, site_count, "site", e);
      CheckIndex(edge.right_site, site_count, "site", e);
    }
    for (const auto& [a, b] : range.same) same_point.Union(a, b);
    kept_edges.insert(kept_edges.end(), range.kept.begin(), range.kept.end());
  }

  FilteredGraph filtered;
  std::set<int> regions;
  for (int e : kept_edges) {
    for (const int v : {diagram.edges[e].source, diagram.edges[e].target}) {
      regions.insert(region[same_point.Find(v)]);
    }
  }
  filtered.region_outlines = boundary_shape->EnclosedRegionOutlines(regions);
  boundary_shape.reset();

  ChainGraph& graph = filtered.graph;
  std::vector<ChainSegment> segments;
  segments.reserve(kept_edges.size());
  std::vector<int> chain_vertex(vertex_count, -1);
  auto vertex_of = [&](int voronoi_vertex) {
    const int root = same_point.Find(voronoi_vertex);
    if (chain_vertex[root] < 0) {
      chain_vertex[root] = static_cast<int>(graph.vertices.size());
      graph.vertices.push_back({diagram.positions[root], diagram.clearances[root], false});
      filtered.vertex_region.push_back(region[root]);
    }
    return chain_vertex[root];
  };
  for (int e : kept_edges) {
    const PlainVoronoi::Edge& edge = diagram.edges[e];
    ChainSegment segment;
    segment.source = vertex_of(edge.source);
    segment.target = vertex_of(edge.target);
    if (segment.source == segment.target) continue;
    segment.left_site = edge.left_site;
    segment.right_site = edge.right_site;
    segment.clearance_px = edge.clearance_px;
    segments.push_back(segment);
  }
  // The chains through degree-2 vertices, built once (not one edge per
  // segment joined afterwards).
  graph.JoinSegments(segments, diagram.sites);
  return filtered;
}

}  // namespace areagraph

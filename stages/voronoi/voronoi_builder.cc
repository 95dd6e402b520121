#include "stages/voronoi/voronoi_builder.h"

#include <cmath>
#include <vector>

#include "stages/geometry/disjoint_sets.h"
#include "stages/geometry/parallel_ranges.h"
#include "stages/geometry/site_triangulation_cgal.h"

namespace areagraph {
namespace {

using SiteDelaunay = site_cgal::Delaunay;
using Face = SiteDelaunay::Face_handle;

// How many faces (or Voronoi vertices) ahead the loops below ask for the
// memory they will read at random (__builtin_prefetch): the dual of a big map
// waits on memory more than it computes.
constexpr int kAhead = 16;

// The finite faces as flat arrays, face k being the k-th of CGAL's finite
// face iteration: its three vertices' site indices and its three
// neighbours' numbers (-1: infinite), slot i for vertex i and the neighbour
// across from it, as in the face itself. Read in face order, with the few
// random reads asked for ahead, these replace following the faces' pointers
// in every pass: CGAL's faces (72 bytes each, in slots that insertion
// reused, so neighbours lie anywhere) and vertices miss the caches on a big
// map (tens of millions of cells).
struct FaceArrays {
  std::vector<int> site;
  std::vector<int> neighbor;
  // Where each range of ParallelRangeCount(faces, kMinFacesPerRange) starts.
  std::vector<SiteDelaunay::Finite_faces_iterator> range_start;

  int Count() const { return static_cast<int>(site.size() / 3); }
};

// How many faces a range of the dual's passes holds at least: a range is a
// task on OpenCV's pool, which costs some microseconds to wake; below this
// (small maps) the passes run in the calling thread.
constexpr size_t kMinFacesPerRange = 16384;

// Numbers the finite faces (face info's number, in iteration order) and fills
// their arrays; neighbouring faces whose circumcircles are the same circle
// are merged in `sets`. The triangulation must be fresh (every face's number
// -1, as CGAL makes them), so that infinite faces keep -1. One serial pass
// numbers the faces and notes where each range starts; the ranges then read
// their faces' sites and neighbours' numbers (the random reads) at once,
// each pair of neighbours tested for co-circularity from its later face (the
// fourth point exactly on the circle is an exact predicate, the same from
// either face). The unions run afterwards in face order, as the serial loop
// made them (the labels, first appearance, would not depend on it anyway).
FaceArrays NumberAndMergeFaces(SiteDelaunay& dt, DisjointSets* sets) {
  FaceArrays faces;
  const size_t face_count = dt.number_of_faces();
  faces.site.resize(3 * face_count);
  faces.neighbor.resize(3 * face_count);
  const int ranges = ParallelRangeCount(face_count, kMinFacesPerRange);
  std::vector<SiteDelaunay::Finite_faces_iterator>& range_start = faces.range_start;
  range_start.reserve(ranges);
  int count = 0;
  for (auto f = dt.finite_faces_begin(); f != dt.finite_faces_end(); ++f) {
    if (range_start.size() < static_cast<size_t>(ranges) &&
        static_cast<size_t>(count) ==
            ParallelRangeBegin(face_count, ranges, static_cast<int>(range_start.size()))) {
      range_start.push_back(f);
    }
    f->info().number = count++;
  }
  const auto side_of_circle = dt.geom_traits().side_of_oriented_circle_2_object();
  std::vector<std::vector<std::pair<int, int>>> unions(ranges);
  ForEachRange(face_count, ranges, [&](size_t begin, size_t end, int range) {
    auto f = range_start[range];
    // CGAL reuses the slots of faces that insertion destroyed, so a face's
    // neighbours and vertices lie anywhere in memory: what they hold is asked
    // for kAhead faces early. (Past the range's end the faces are still
    // finite ones or the end; the few infinite ones only make a prefetch
    // useless.)
    auto ahead = f;
    for (size_t k = begin; k < end && k < begin + kAhead; ++k) ++ahead;
    std::vector<std::pair<int, int>>& merged = unions[range];
    for (size_t number = begin; number < end; ++number, ++f) {
      if (ahead != dt.finite_faces_end()) {
        for (int i = 0; i < 3; ++i) {
          __builtin_prefetch(&ahead->neighbor(i)->info());
          __builtin_prefetch(&*ahead->vertex(i));
        }
        ++ahead;
      }
      int* site = &faces.site[3 * number];
      int* neighbor = &faces.neighbor[3 * number];
      for (int i = 0; i < 3; ++i) site[i] = f->vertex(i)->info();
      const auto& p = f->vertex(0)->point();
      const auto& q = f->vertex(1)->point();
      const auto& r = f->vertex(2)->point();
      for (int i = 0; i < 3; ++i) {
        const Face n = f->neighbor(i);
        const int other = n->info().number;
        neighbor[i] = other;
        if (other < 0 || other >= static_cast<int>(number)) continue;  // infinite, or later
        if (side_of_circle(p, q, r, n->vertex(n->index(f))->point()) ==
            CGAL::ON_ORIENTED_BOUNDARY) {
          merged.emplace_back(other, static_cast<int>(number));
        }
      }
    }
  });
  for (const auto& merged : unions) {
    for (const auto& [a, b] : merged) sets->Union(a, b);
  }
  return faces;
}

// Smallest distance from the part of the bisector between `from` and `to` to
// the two sites: half their distance when their midpoint lies on that part,
// else the nearer end's clearance. The part is from + t * direction for t in
// [0, t_max]: t_max is 1 for segments and infinity for rays.
double EdgeClearance(const Eigen::Vector2d& from, const Eigen::Vector2d& direction, double t_max,
                     double from_clearance, double to_clearance, const Eigen::Vector2d& site_a,
                     const Eigen::Vector2d& site_b) {
  const Eigen::Vector2d midpoint = 0.5 * (site_a + site_b);
  const double length2 = direction.squaredNorm();
  const double t = length2 > 0 ? (midpoint - from).dot(direction) / length2 : 0.0;
  if (t >= 0 && t <= t_max) return 0.5 * (site_b - site_a).norm();
  return std::min(from_clearance, to_clearance);
}

// Fills the diagram's vertex and edge arrays with the dual of the sites'
// Delaunay triangulation `dt` (see BuildVoronoiDiagram); each vertex's info
// is its index in `sites`. The arrays take about the memory of the plain
// structs the messages of format 1 were made from.
void AddDualOfTriangulation(SiteDelaunay& dt, const std::vector<Eigen::Vector2d>& sites,
                            const VoronoiBuildOptions& options, proto::VoronoiDiagram* diagram) {
  if (dt.dimension() < 2) return;

  DisjointSets cocircular(dt.number_of_faces());
  FaceArrays faces = NumberAndMergeFaces(dt, &cocircular);
  const int face_count = faces.Count();
  int vertex_count = 0;
  const std::vector<int> vertex_of_face = cocircular.DenseLabels(&vertex_count);
  auto point = [&](int site) { return site_cgal::Point(sites[site].x(), sites[site].y()); };

  // One Voronoi vertex per circle, placed at the first face's circumcentre:
  // vertices are numbered in order of their first face. Written straight
  // into the diagram (a copy beside it would be fresh pages to fault in),
  // each range of vertices into its own part of the arrays.
  std::vector<int> first_face(vertex_count);
  for (int f = 0, next = 0; f < face_count && next < vertex_count; ++f) {
    if (vertex_of_face[f] == next) first_face[next++] = f;
  }
  auto& xs = *diagram->mutable_vertex_x();
  auto& ys = *diagram->mutable_vertex_y();
  auto& clearances = *diagram->mutable_vertex_clearance_px();
  xs.Reserve(vertex_count);
  ys.Reserve(vertex_count);
  clearances.Reserve(vertex_count);
  double* x_out = xs.AddNAlreadyReserved(vertex_count);
  double* y_out = ys.AddNAlreadyReserved(vertex_count);
  double* clearance_out = clearances.AddNAlreadyReserved(vertex_count);
  const int vertex_ranges = ParallelRangeCount(vertex_count, kMinFacesPerRange);
  ForEachRange(vertex_count, vertex_ranges, [&](size_t begin, size_t end, int) {
    for (size_t v = begin; v < end; ++v) {
      if (v + kAhead < end) {
        for (int i = 0; i < 3; ++i) {
          __builtin_prefetch(
              &sites[faces.site[3 * static_cast<size_t>(first_face[v + kAhead]) + i]]);
        }
      }
      const int* site = &faces.site[3 * static_cast<size_t>(first_face[v])];
      const site_cgal::Point first = point(site[0]);
      const auto centre = dt.circumcenter(first, point(site[1]), point(site[2]));
      x_out[v] = centre.x();
      y_out[v] = centre.y();
      clearance_out[v] = std::sqrt(CGAL::squared_distance(centre, first));
    }
  });
  auto position = [&](int vertex) { return Eigen::Vector2d(x_out[vertex], y_out[vertex]); };

  // Each slot's edge, in place of the neighbour: its target vertex, kRay, or
  // kNotHere when the neighbour has the lower number (the edge is its). A
  // loop of independent loads, which the processor overlaps.
  constexpr int kRay = -1, kNotHere = -2;
  std::vector<int>& target_of = faces.neighbor;
  const int face_ranges = ParallelRangeCount(face_count, kMinFacesPerRange);
  // How many edges and rays each range of faces writes, so that every range
  // writes its own part of the arrays, in face order.
  std::vector<int> range_edges(face_ranges + 1, 0), range_rays(face_ranges + 1, 0);
  ForEachRange(face_count, face_ranges, [&](size_t begin, size_t end, int range) {
    int edges = 0, rays = 0;
    for (size_t slot = 3 * begin; slot < 3 * end; ++slot) {
      const int other = target_of[slot];
      const int number = static_cast<int>(slot / 3);
      int target = other;
      if (other >= 0) target = other < number ? kNotHere : vertex_of_face[other];
      target_of[slot] = target;
      if (target == kNotHere || target == vertex_of_face[number]) continue;
      if (target == kRay) {
        if (!options.keep_rays) continue;
        ++rays;
      }
      ++edges;
    }
    range_edges[range + 1] = edges;
    range_rays[range + 1] = rays;
  });
  for (int range = 0; range < face_ranges; ++range) {
    range_edges[range + 1] += range_edges[range];
    range_rays[range + 1] += range_rays[range];
  }

  // Each Delaunay edge once, from its finite face with the lower number
  // towards the other face. (CGAL's edge iterator picks the side by comparing
  // face addresses, which would make the output depend on the heap's history.)
  // Sized once: on a large map, doubling would hold two copies for a moment.
  const int edge_count = range_edges[face_ranges], ray_count = range_rays[face_ranges];
  auto add_ints = [&](google::protobuf::RepeatedField<int32_t>* field) {
    field->Reserve(edge_count);
    return field->AddNAlreadyReserved(edge_count);
  };
  auto add_doubles = [&](google::protobuf::RepeatedField<double>* field, int n) {
    field->Reserve(n);
    return field->AddNAlreadyReserved(n);
  };
  int* source_out = add_ints(diagram->mutable_edge_source());
  int* target_out = add_ints(diagram->mutable_edge_target());
  int* left_out = add_ints(diagram->mutable_edge_left_site());
  int* right_out = add_ints(diagram->mutable_edge_right_site());
  double* edge_clearance_out = add_doubles(diagram->mutable_edge_clearance_px(), edge_count);
  double* ray_x_out = add_doubles(diagram->mutable_ray_direction_x(), ray_count);
  double* ray_y_out = add_doubles(diagram->mutable_ray_direction_y(), ray_count);
  ForEachRange(face_count, face_ranges, [&](size_t begin, size_t end, int range) {
    int out = range_edges[range], ray = range_rays[range];
    for (size_t number = begin; number < end; ++number) {
      if (number + kAhead < end) {
        const size_t first = 3 * (number + kAhead);
        for (size_t slot = first; slot < first + 3; ++slot) {
          if (const int target = target_of[slot]; target >= 0) {
            __builtin_prefetch(&x_out[target]);
            __builtin_prefetch(&y_out[target]);
            __builtin_prefetch(&clearance_out[target]);
          }
          __builtin_prefetch(&sites[faces.site[slot]]);
        }
      }
      const int* site = &faces.site[3 * number];
      const int source = vertex_of_face[number];
      for (int i = 0; i < 3; ++i) {
        const int target = target_of[3 * number + i];
        if (target == kNotHere) continue;
        const bool is_ray = target == kRay;
        if (is_ray && !options.keep_rays) continue;
        if (source == target) continue;

        // The face is counter-clockwise in CGAL's (y up) sense, so moving out
        // of it across the edge ccw(i) -> cw(i), vertex ccw(i) is on the
        // CGAL-right, which is the left when y points down.
        const int left = site[SiteDelaunay::ccw(i)];
        const int right = site[SiteDelaunay::cw(i)];
        const Eigen::Vector2d& left_site = sites[left];
        const Eigen::Vector2d& right_site = sites[right];

        double clearance;
        if (is_ray) {
          // Perpendicular to the hull edge, pointing away from the face: the
          // face is on the CGAL-left of left_site -> right_site, so take its
          // right normal.
          const Eigen::Vector2d along = right_site - left_site;
          const Eigen::Vector2d direction = Eigen::Vector2d(along.y(), -along.x()).normalized();
          ray_x_out[ray] = direction.x();
          ray_y_out[ray] = direction.y();
          ++ray;
          clearance = EdgeClearance(position(source), direction, INFINITY, clearance_out[source],
                                    clearance_out[source], left_site, right_site);
        } else {
          clearance =
              EdgeClearance(position(source), position(target) - position(source), 1.0,
                            clearance_out[source], clearance_out[target], left_site, right_site);
        }
        source_out[out] = source;
        target_out[out] = target;
        left_out[out] = left;
        right_out[out] = right;
        edge_clearance_out[out] = clearance;
        ++out;
      }
    }
  });
  // Each face now names its Voronoi vertex (prune's locate walks start there).
  ForEachRange(face_count, static_cast<int>(faces.range_start.size()),
               [&](size_t begin, size_t end, int range) {
                 auto face = faces.range_start[range];
                 for (size_t number = begin; number < end; ++number, ++face) {
                   face->info().number = vertex_of_face[number];
                 }
               });
}

}  // namespace

proto::VoronoiDiagram BuildVoronoiDiagram(const std::vector<Eigen::Vector2d>& sites,
                                          const VoronoiBuildOptions& options) {
  return BuildVoronoiDiagram(sites, options, nullptr);
}

proto::VoronoiDiagram BuildVoronoiDiagram(const std::vector<Eigen::Vector2d>& sites,
                                          const VoronoiBuildOptions& options,
                                          SiteTriangulationPtr* triangulation_out) {
  proto::VoronoiDiagram diagram;
  diagram.mutable_site_x()->Reserve(int(sites.size()));
  diagram.mutable_site_y()->Reserve(int(sites.size()));
  for (const Eigen::Vector2d& site : sites) {
    diagram.add_site_x(site.x());
    diagram.add_site_y(site.y());
  }
  SiteTriangulationPtr triangulation = TriangulateIndexedSites(sites);
  AddDualOfTriangulation(triangulation->dt, sites, options, &diagram);
  if (triangulation_out != nullptr) *triangulation_out = std::move(triangulation);
  return diagram;
}

}  // namespace areagraph

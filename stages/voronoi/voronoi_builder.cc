#include "stages/voronoi/voronoi_builder.h"

#include <cmath>
#include <vector>

#include "stages/geometry/disjoint_sets.h"
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
// map (lab_a tiled 8 x 8).
struct FaceArrays {
  std::vector<int> site;
  std::vector<int> neighbor;

  int Count() const { return static_cast<int>(site.size() / 3); }
};

// Numbers the finite faces (face info's number, in iteration order), fills
// their arrays and merges neighbouring faces whose circumcircles are the
// same circle, all in one pass over CGAL's faces. The triangulation must be
// fresh (every face's number -1, as CGAL makes them), so that a neighbour
// already numbered is one that came before: the pair's two slots are then
// filled together, and infinite faces keep -1. Co-circular is an exact
// predicate (the fourth point exactly on the circle, no tolerance), and the
// same for either face of a pair, so each pair is tested once, from its
// later face.
FaceArrays NumberAndMergeFaces(SiteDelaunay& dt, DisjointSets* sets) {
  FaceArrays faces;
  const size_t face_count = dt.number_of_faces();
  faces.site.resize(3 * face_count);
  faces.neighbor.assign(3 * face_count, -1);
  const auto side_of_circle = dt.geom_traits().side_of_oriented_circle_2_object();
  // CGAL reuses the slots of faces that insertion destroyed, so a face's
  // neighbours and vertices lie anywhere in memory: what they hold is asked
  // for kAhead faces early.
  // (All faces: cheaper to step through than the finite ones, and the few
  // infinite ones only make a prefetch useless.)
  auto ahead = dt.all_faces_begin();
  for (int k = 0; k < kAhead && ahead != dt.all_faces_end(); ++k) ++ahead;
  int count = 0;
  for (auto f = dt.finite_faces_begin(); f != dt.finite_faces_end(); ++f) {
    if (ahead != dt.all_faces_end()) {
      for (int i = 0; i < 3; ++i) {
        __builtin_prefetch(&ahead->neighbor(i)->info());
        __builtin_prefetch(&*ahead->vertex(i));
      }
      ++ahead;
    }
    const int number = count++;
    f->info().number = number;
    int* site = &faces.site[3 * static_cast<size_t>(number)];
    int* neighbor = &faces.neighbor[3 * static_cast<size_t>(number)];
    for (int i = 0; i < 3; ++i) site[i] = f->vertex(i)->info();
    const auto& p = f->vertex(0)->point();
    const auto& q = f->vertex(1)->point();
    const auto& r = f->vertex(2)->point();
    for (int i = 0; i < 3; ++i) {
      const Face n = f->neighbor(i);
      const int other = n->info().number;
      if (other < 0) continue;  // infinite, or numbered later (it fills this slot)
      const int slot = n->index(f);
      neighbor[i] = other;
      faces.neighbor[3 * static_cast<size_t>(other) + slot] = number;
      if (side_of_circle(p, q, r, n->vertex(slot)->point()) == CGAL::ON_ORIENTED_BOUNDARY) {
        sets->Union(other, number);
      }
    }
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
  // into the diagram (a copy beside it would be fresh pages to fault in).
  auto& xs = *diagram->mutable_vertex_x();
  auto& ys = *diagram->mutable_vertex_y();
  auto& clearances = *diagram->mutable_vertex_clearance_px();
  xs.Reserve(vertex_count);
  ys.Reserve(vertex_count);
  clearances.Reserve(vertex_count);
  for (int f = 0; f < face_count && xs.size() < vertex_count; ++f) {
    if (f + kAhead < face_count) {
      for (int i = 0; i < 3; ++i) {
        __builtin_prefetch(&sites[faces.site[3 * static_cast<size_t>(f + kAhead) + i]]);
      }
    }
    if (vertex_of_face[f] != xs.size()) continue;
    const int* site = &faces.site[3 * static_cast<size_t>(f)];
    const site_cgal::Point first = point(site[0]);
    const auto centre = dt.circumcenter(first, point(site[1]), point(site[2]));
    xs.AddAlreadyReserved(centre.x());
    ys.AddAlreadyReserved(centre.y());
    clearances.AddAlreadyReserved(std::sqrt(CGAL::squared_distance(centre, first)));
  }
  auto position = [&](int vertex) { return Eigen::Vector2d(xs[vertex], ys[vertex]); };

  // Each slot's edge, in place of the neighbour: its target vertex, kRay, or
  // kNotHere when the neighbour has the lower number (the edge is its). A
  // loop of independent loads, which the processor overlaps.
  constexpr int kRay = -1, kNotHere = -2;
  std::vector<int>& target_of = faces.neighbor;
  for (size_t slot = 0; slot < target_of.size(); ++slot) {
    const int other = target_of[slot];
    if (other >= 0) {
      target_of[slot] = other < static_cast<int>(slot / 3) ? kNotHere : vertex_of_face[other];
    }
  }

  // Each Delaunay edge once, from its finite face with the lower number
  // towards the other face. (CGAL's edge iterator picks the side by comparing
  // face addresses, which would make the output depend on the heap's history.)
  // Sized once: on a large map, doubling would hold two copies for a moment.
  const int most_edges = static_cast<int>(dt.number_of_vertices()) + face_count;
  for (auto* field : {diagram->mutable_edge_source(), diagram->mutable_edge_target(),
                      diagram->mutable_edge_left_site(), diagram->mutable_edge_right_site()}) {
    field->Reserve(most_edges);
  }
  diagram->mutable_edge_clearance_px()->Reserve(most_edges);
  for (int number = 0; number < face_count; ++number) {
    if (number + kAhead < face_count) {
      const size_t first = 3 * static_cast<size_t>(number + kAhead);
      for (size_t slot = first; slot < first + 3; ++slot) {
        if (const int target = target_of[slot]; target >= 0) {
          __builtin_prefetch(&xs[target]);
          __builtin_prefetch(&ys[target]);
          __builtin_prefetch(&clearances[target]);
        }
        __builtin_prefetch(&sites[faces.site[slot]]);
      }
    }
    const int* site = &faces.site[3 * static_cast<size_t>(number)];
    const int source = vertex_of_face[number];
    for (int i = 0; i < 3; ++i) {
      const int target = target_of[3 * static_cast<size_t>(number) + i];
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
        diagram->add_ray_direction_x(direction.x());
        diagram->add_ray_direction_y(direction.y());
        clearance = EdgeClearance(position(source), direction, INFINITY, clearances[source],
                                  clearances[source], left_site, right_site);
      } else {
        clearance = EdgeClearance(position(source), position(target) - position(source), 1.0,
                                  clearances[source], clearances[target], left_site, right_site);
      }
      diagram->add_edge_source(source);
      diagram->add_edge_target(target);
      diagram->add_edge_left_site(left);
      diagram->add_edge_right_site(right);
      diagram->add_edge_clearance_px(clearance);
    }
  }
  // Each face now names its Voronoi vertex (prune's locate walks start there).
  int number = 0;
  for (auto face = dt.finite_faces_begin(); face != dt.finite_faces_end(); ++face) {
    face->info().number = vertex_of_face[number++];
  }
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

#include "stages/geometry/site_alpha_shape.h"

#include <algorithm>
#include <map>
#include <type_traits>
#include <vector>

#include "stages/geometry/parallel_ranges.h"
#include "stages/geometry/site_triangulation_cgal.h"

namespace areagraph {
namespace {

using FaceInfo = SiteFaceInfo;
using Kernel = site_cgal::Kernel;
using Delaunay = site_cgal::Delaunay;
using Face = Delaunay::Face_handle;

// Below these counts per range the work runs in the calling thread (a
// range is a task on OpenCV's pool, which costs some microseconds to wake).
constexpr size_t kMinPointsPerRange = 4096;
constexpr size_t kMinFacesPerRange = 16384;
// How many points ahead EnclosedRegionsAt asks for their start faces.
constexpr int kAhead = 8;

Eigen::Vector2d ToVector(const Kernel::Point_2& point) { return {point.x(), point.y()}; }

Eigen::Vector2d Centroid(const Face& face) {
  return (ToVector(face->vertex(0)->point()) + ToVector(face->vertex(1)->point()) +
          ToVector(face->vertex(2)->point())) /
         3.0;
}

double TriangleArea(const Face& face) {
  const Eigen::Vector2d a = ToVector(face->vertex(0)->point());
  const Eigen::Vector2d b = ToVector(face->vertex(1)->point());
  const Eigen::Vector2d c = ToVector(face->vertex(2)->point());
  return 0.5 * std::abs((b - a).x() * (c - a).y() - (b - a).y() * (c - a).x());
}

double SignedArea(const PointList& ring) {
  double twice = 0;
  for (size_t i = 0; i < ring.size(); ++i) {
    const Eigen::Vector2d& p = ring[i];
    const Eigen::Vector2d& q = ring[(i + 1) % ring.size()];
    twice += p.x() * q.y() - q.x() * p.y();
  }
  return 0.5 * twice;
}

proto::Ring ToProtoRing(const PointList& points) {
  proto::Ring ring;
  SetPackedRing(points, &ring);
  return ring;
}

}  // namespace

struct SiteAlphaShape::Impl {
  SiteTriangulationPtr triangulation;
  Delaunay& shape;
  // Where the last walk (RoomAt, EnclosedRegionAt) ended: the next one
  // starts there, and for a point on an edge or vertex the face a walk
  // returns depends on where it starts.
  Face hint;
  // Points of EnclosedRegionAt whose walk from `hint` was put off (their
  // answer did not depend on it); run before `hint` is next needed.
  std::vector<Kernel::Point_2> unwalked;
  // A face of each Voronoi vertex (face info's `number`, set by the Voronoi
  // builder); built on first use, empty when the faces name none.
  std::vector<Face> vertex_face;
  bool vertex_faces_built = false;
  int enclosed_regions = 0;  // found by FindEnclosedRegions
  // Where ranges of all faces start (FaceRangeStarts), once found.
  std::vector<Delaunay::All_faces_iterator> face_range_starts;
  // Rooms: the id each face label (DetectRooms') has now, RenumberRooms
  // composed here instead of rewriting every face; the faces take them when
  // RoomOutlines walks them. And the rooms' areas, summed as DetectRooms
  // labels (in face order), until the first renumbering.
  std::vector<int> room_ids;
  std::vector<double> room_areas;
  bool areas_valid = false;

  int RoomId(const Face& face) const {
    const int label = face->info().room;
    return label < 0 || label >= static_cast<int>(room_ids.size()) ? -1 : room_ids[label];
  }

  // `triangulation` holds the points inserted as Alpha_shape_2's constructor
  // does (one range insert), so the triangulation of co-circular grid points
  // is the same.
  Impl(SiteTriangulationPtr triangulation, double alpha)
      : triangulation(std::move(triangulation)), shape(this->triangulation->dt) {
    if (HasFaces()) Classify(alpha);
  }

  bool HasFaces() const { return shape.dimension() == 2; }

  // The alpha complex for one alpha, with Alpha_shape_2's rules and functors
  // in GENERAL mode (as ComputeAlphaComplex), without its alpha spectrum
  // (maps of every face and edge by the alpha at which they appear), which
  // cost most of ag-prune and ag-cut: a finite face is interior when its
  // squared circumradius is <= alpha; an edge is in the complex when a face
  // beside it is interior, or when it is finite, its squared half-length is
  // <= alpha and no opposite vertex lies strictly inside its diametral
  // circle (singular).
  void Classify(double alpha) {
    const auto& traits = shape.geom_traits();
    const auto squared_radius = traits.compute_squared_radius_2_object();
    const auto side_of_bounded_circle = traits.side_of_bounded_circle_2_object();
    // Two passes over ranges of the faces: each face's flags are its own,
    // the second pass reads the neighbours' first.
    ForEachFaceRange([&](Delaunay::All_faces_iterator face, size_t count) {
      for (; count > 0; --count, ++face) {
        face->info().interior = !shape.is_infinite(face) &&
                                squared_radius(face->vertex(0)->point(), face->vertex(1)->point(),
                                               face->vertex(2)->point()) <= alpha;
      }
    });
    auto attached = [&](const Face& face, int i) {
      return !shape.is_infinite(face) &&
             side_of_bounded_circle(face->vertex(Delaunay::cw(i))->point(),
                                    face->vertex(Delaunay::ccw(i))->point(),
                                    face->vertex(i)->point()) == CGAL::ON_BOUNDED_SIDE;
    };
    ForEachFaceRange([&](Delaunay::All_faces_iterator it, size_t count) {
      for (; count > 0; --count, ++it) {
        const Face face = it;
        unsigned char bits = 0;
        for (int i = 0; i < 3; ++i) {
          const Face neighbor = face->neighbor(i);
          bool in_complex = face->info().interior || neighbor->info().interior;
          if (!in_complex && !shape.is_infinite(face, i)) {
            in_complex = squared_radius(face->vertex(Delaunay::ccw(i))->point(),
                                        face->vertex(Delaunay::cw(i))->point()) <= alpha &&
                         !attached(face, i) && !attached(neighbor, neighbor->index(face));
          }
          if (in_complex) bits |= static_cast<unsigned char>(1 << i);
        }
        face->info().in_complex = bits;
      }
    });
  }

  // Where each range of all faces starts (ParallelRangeCount's split): one
  // pass through the face container, on first use (the triangulation does
  // not change here, so they stay valid).
  const std::vector<Delaunay::All_faces_iterator>& FaceRangeStarts() {
    if (!face_range_starts.empty()) return face_range_starts;
    const size_t count = shape.tds().number_of_faces();
    const int ranges = ParallelRangeCount(count, kMinFacesPerRange);
    std::vector<Delaunay::All_faces_iterator>& starts = face_range_starts;
    starts.reserve(ranges);
    starts.push_back(shape.all_faces_begin());
    if (ranges > 1) {
      size_t index = 0;
      for (auto face = shape.all_faces_begin(); face != shape.all_faces_end(); ++face, ++index) {
        if (index == ParallelRangeBegin(count, ranges, static_cast<int>(starts.size()))) {
          starts.push_back(face);
          if (static_cast<int>(starts.size()) == ranges) break;
        }
      }
    }
    return starts;
  }

  // body(first, count, range) for each range of all faces (FaceRangeStarts),
  // in parallel: what each writes must be its own faces'.
  template <typename Body>
  void ForEachFaceRange(const Body& body) {
    const std::vector<Delaunay::All_faces_iterator>& starts = FaceRangeStarts();
    ForEachRange(shape.tds().number_of_faces(), static_cast<int>(starts.size()),
                 [&](size_t begin, size_t end, int range) {
                   if constexpr (std::is_invocable_v<Body, Delaunay::All_faces_iterator, size_t>) {
                     body(starts[range], end - begin);
                   } else {
                     body(starts[range], end - begin, range);
                   }
                 });
  }

  // Sets `field` of every face (finite only, unless `infinite_too`).
  template <typename Field, typename Value>
  void ResetFaces(Field FaceInfo::*field, Value value, bool infinite_too) {
    ForEachFaceRange([&](Delaunay::All_faces_iterator face, size_t count) {
      for (; count > 0; --count, ++face) {
        if (infinite_too || !shape.is_infinite(face)) face->info().*field = value;
      }
    });
  }

  // Alpha_shape_2::classify(face) != EXTERIOR.
  static bool Interior(const Face& face) { return face->info().interior; }
  // Alpha_shape_2::classify(face, i) != EXTERIOR.
  static bool InComplex(const Face& face, int i) { return face->info().in_complex & (1 << i); }

  // Labels edge-connected groups of `member` faces, crossing only edges that
  // `connects` accepts; `label` selects the field to write. Returns the count.
  // Labels follow the seeds' (face) order; within a group the order of the
  // search does not matter, so it runs depth first on a reused stack.
  template <typename Member, typename Connects>
  int LabelRegions(const Member& member, const Connects& connects, int FaceInfo::*label) {
    int count = 0;
    ResetFaces(label, -1, /*infinite_too=*/false);
    std::vector<Face> stack;
    for (Face seed : shape.finite_face_handles()) {
      if (seed->info().*label >= 0 || !member(seed)) continue;
      seed->info().*label = count;
      stack.push_back(seed);
      Spread(&stack, [&](const Face& face, int i, const Face& next) {
        if (shape.is_infinite(next) || next->info().*label >= 0) return false;
        if (!connects(face, i) || !member(next)) return false;
        next->info().*label = count;
        return true;
      });
      ++count;
    }
    return count;
  }

  // Walks from the faces on `stack` (emptied) across their edges, depth
  // first: join(face, i, next) decides, and marks, whether `next`, across
  // edge i of `face`, is walked from too. Only the set reached matters.
  template <typename Join>
  static void Spread(std::vector<Face>* stack, const Join& join) {
    while (!stack->empty()) {
      const Face face = stack->back();
      stack->pop_back();
      for (int i = 0; i < 3; ++i) {
        const Face next = face->neighbor(i);
        if (join(face, i, next)) stack->push_back(next);
      }
    }
  }

  // The closed boundary rings of every labelled region, keyed by label. Each
  // ring keeps its region on the left; at a vertex where the region touches
  // itself the walk stays within the faces it came through.
  std::map<int, std::vector<PointList>> RegionRings(int FaceInfo::*label, int only = -1) {
    ResetFaces(&FaceInfo::walked, static_cast<unsigned char>(0), /*infinite_too=*/true);
    std::map<int, std::vector<PointList>> rings;
    auto on_boundary = [&](const Face& face, int i) {
      const Face other = face->neighbor(i);
      return shape.is_infinite(other) || other->info().*label != face->info().*label;
    };
    for (Face start : shape.finite_face_handles()) {
      const int region = start->info().*label;
      if (region < 0 || (only >= 0 && region != only)) continue;
      for (int start_edge = 0; start_edge < 3; ++start_edge) {
        if ((start->info().walked & (1 << start_edge)) || !on_boundary(start, start_edge)) continue;
        PointList ring;
        Face face = start;
        int edge = start_edge;
        do {
          face->info().walked |= static_cast<unsigned char>(1 << edge);
          ring.push_back(ToVector(face->vertex(Delaunay::ccw(edge))->point()));
          const auto pivot = face->vertex(Delaunay::cw(edge));
          // Turn around the edge's end vertex through faces of the region
          // until the next edge with another region beyond it.
          edge = Delaunay::cw(face->index(pivot));
          while (!on_boundary(face, edge)) {
            face = face->neighbor(edge);
            edge = Delaunay::cw(face->index(pivot));
          }
        } while (face != start || edge != start_edge);
        rings[region].push_back(std::move(ring));
      }
    }
    return rings;
  }

  static proto::Polygon ToPolygon(const std::vector<PointList>& rings, bool with_holes) {
    proto::Polygon polygon;
    int outer = -1;
    for (size_t i = 0; i < rings.size(); ++i) {
      if (outer < 0 || SignedArea(rings[i]) > SignedArea(rings[outer])) outer = static_cast<int>(i);
    }
    if (outer < 0) return polygon;
    *polygon.mutable_outer() = ToProtoRing(rings[outer]);
    if (with_holes) {
      for (size_t i = 0; i < rings.size(); ++i) {
        if (static_cast<int>(i) != outer) *polygon.add_holes() = ToProtoRing(rings[i]);
      }
    }
    return polygon;
  }

  Face Locate(const Eigen::Vector2d& point) {
    CatchUpHint();
    hint = shape.locate(Kernel::Point_2(point.x(), point.y()), hint);
    return hint;
  }

  // Runs the walks EnclosedRegionAt put off, so that `hint` is where the
  // plain walks would have left it.
  void CatchUpHint() {
    for (const Kernel::Point_2& point : unwalked) hint = shape.locate(point, hint);
    unwalked.clear();
  }

  static int FilledRegion(const Delaunay& shape, const Face& face) {
    return shape.is_infinite(face) ? -1 : face->info().filled_region;
  }

  // What EnclosedRegionAt(point, vertex) finds walking from the vertex's
  // face `start` (const: no state read or written), and what the state
  // between calls needs of it (Apply). A point inside a face has one answer,
  // however the walk starts, so the short walk from the vertex's own face
  // gives it (kFace: the plain walk would end there too). A point on an edge
  // or vertex (or outside the hull) gets the face where the plain walk from
  // `hint` stops; when all the faces it could stop in agree, that walk
  // (needed only as the next start) is put off (kAgree), else it runs
  // (kWalk), after those put off before. Without `start`: kWalk.
  enum class Kind : char { kFace, kAgree, kWalk };
  struct Probe {
    Kind kind;
    int region;
    Face face;
  };
  Probe ProbeAt(const Eigen::Vector2d& point, const Face& start) const {
    if (start == Face()) return {Kind::kWalk, -1, Face()};
    const Kernel::Point_2 at(point.x(), point.y());
    Face found = shape.inexact_locate(at, start);
    Delaunay::Locate_type type = Delaunay::OUTSIDE_CONVEX_HULL;
    int index = 4;
    if (!shape.is_infinite(found)) {
      // Where `at` lies in the face the inexact walk found, exactly (as the
      // exact walk classifies it); a negative side means it is not there.
      const auto orientation = shape.geom_traits().orientation_2_object();
      const Kernel::Point_2& a = found->vertex(0)->point();
      const Kernel::Point_2& b = found->vertex(1)->point();
      const Kernel::Point_2& c = found->vertex(2)->point();
      const CGAL::Orientation o0 = orientation(a, b, at), o1 = orientation(b, c, at),
                              o2 = orientation(c, a, at);
      if (o0 == CGAL::NEGATIVE || o1 == CGAL::NEGATIVE || o2 == CGAL::NEGATIVE) {
        found = shape.locate(at, type, index, found);
      } else {
        const int zeros = (o0 == CGAL::ZERO) + (o1 == CGAL::ZERO) + (o2 == CGAL::ZERO);
        if (zeros == 0) {
          type = Delaunay::FACE;
        } else if (zeros == 1) {
          type = Delaunay::EDGE;
          index = o0 == CGAL::ZERO ? 2 : (o1 == CGAL::ZERO ? 0 : 1);
        } else {
          type = Delaunay::VERTEX;
          index = o0 != CGAL::ZERO ? 2 : (o1 != CGAL::ZERO ? 0 : 1);
        }
      }
    } else {
      found = shape.locate(at, type, index, found);
    }
    if (type == Delaunay::FACE) return {Kind::kFace, found->info().filled_region, found};
    const int region = FilledRegion(shape, found);
    bool agree = true;
    if (type == Delaunay::EDGE) {
      agree = FilledRegion(shape, found->neighbor(index)) == region;
    } else if (type == Delaunay::VERTEX) {
      auto around = shape.incident_faces(found->vertex(index)), end = around;
      do {
        agree = FilledRegion(shape, around) == region;
      } while (agree && ++around != end);
    }
    return {agree ? Kind::kAgree : Kind::kWalk, region, Face()};
  }

  // The state change of a probe of `point`, and its answer (kWalk walks).
  int Apply(const Probe& probe, const Eigen::Vector2d& point) {
    switch (probe.kind) {
      case Kind::kFace:
        unwalked.clear();
        hint = probe.face;
        return probe.region;
      case Kind::kAgree:
        unwalked.emplace_back(point.x(), point.y());
        return probe.region;
      case Kind::kWalk:
        break;
    }
    return FilledRegion(shape, Locate(point));
  }

  void PrefetchVertexFace(int vertex) const {
    if (vertex < static_cast<int>(vertex_face.size()) && vertex_face[vertex] != Face()) {
      __builtin_prefetch(&*vertex_face[vertex]);
    }
  }

  // The face of Voronoi vertex `vertex`, or null.
  Face VertexFace(int vertex) {
    if (!vertex_faces_built) {
      vertex_faces_built = true;
      int count = 0;
      for (Face face : shape.finite_face_handles())
        count = std::max(count, face->info().number + 1);
      vertex_face.resize(count);
      for (Face face : shape.finite_face_handles()) {
        if (face->info().number >= 0) vertex_face[face->info().number] = face;
      }
    }
    return vertex >= 0 && vertex < static_cast<int>(vertex_face.size()) ? vertex_face[vertex]
                                                                        : Face();
  }
};

int SiteAlphaShape::NameVertexFaces(const PointList& positions) {
  Impl& impl = *impl_;
  if (!impl.HasFaces() || impl.vertex_faces_built) return 0;
  // Voronoi's triangulation names every finite face.
  if (impl.shape.finite_faces_begin()->info().number >= 0) return 0;
  impl.vertex_faces_built = true;
  impl.vertex_face.assign(positions.size(), Face());
  // The circumcentre as voronoi computes it (same points, same order), so a
  // vertex's first face gives its position exactly; later faces of a circle
  // (and any mismatch) are passed over.
  size_t vertex = 0;
  for (Face face : impl.shape.finite_face_handles()) {
    if (vertex == positions.size()) break;
    const auto centre = impl.shape.circumcenter(face->vertex(0)->point(), face->vertex(1)->point(),
                                                face->vertex(2)->point());
    if (centre.x() == positions[vertex].x() && centre.y() == positions[vertex].y()) {
      impl.vertex_face[vertex++] = face;
    }
  }
  return static_cast<int>(vertex);
}

SiteAlphaShape::SiteAlphaShape(const PointList& sites, double alpha_radius_px)
    : impl_(std::make_unique<Impl>(TriangulateSites(sites), alpha_radius_px * alpha_radius_px)) {}

SiteAlphaShape::SiteAlphaShape(PointList&& sites, double alpha_radius_px)
    : impl_(std::make_unique<Impl>(TriangulateSites(std::move(sites)),
                                   alpha_radius_px * alpha_radius_px)) {}

SiteAlphaShape::SiteAlphaShape(SiteTriangulationPtr triangulation, double alpha_radius_px)
    : impl_(std::make_unique<Impl>(std::move(triangulation), alpha_radius_px * alpha_radius_px)) {}

SiteAlphaShape::~SiteAlphaShape() = default;

std::vector<double> SiteAlphaShape::FindEnclosedRegions() {
  Impl& impl = *impl_;
  impl.enclosed_regions = 0;
  if (!impl.HasFaces()) return {};

  // Outside: what infinity reaches without crossing the alpha complex. Edges
  // of the complex (singular ones too) are walls, so a thin wall whose
  // sliver triangles are wider than alpha still closes the map.
  // (The flags over ranges of the faces; the walk's result does not depend
  // on the order of its starts.)
  std::vector<std::vector<Face>> infinite(impl.FaceRangeStarts().size());
  impl.ForEachFaceRange([&](Delaunay::All_faces_iterator face, size_t count, int range) {
    for (; count > 0; --count, ++face) {
      face->info().outside = impl.shape.is_infinite(face);
      if (face->info().outside) infinite[range].push_back(face);
    }
  });
  std::vector<Face> stack;
  for (const std::vector<Face>& faces : infinite)
    stack.insert(stack.end(), faces.begin(), faces.end());
  Impl::Spread(&stack, [](const Face& face, int i, const Face& next) {
    if (next->info().outside || Impl::InComplex(face, i)) return false;
    next->info().outside = true;
    return true;
  });
  impl.enclosed_regions =
      impl.LabelRegions([](const Face& face) { return !face->info().outside; },
                        [](const Face&, int) { return true; }, &FaceInfo::filled_region);
  std::vector<double> area(impl.enclosed_regions, 0.0);
  for (Face face : impl.shape.finite_face_handles()) {
    if (face->info().filled_region >= 0) area[face->info().filled_region] += TriangleArea(face);
  }
  return area;
}

int SiteAlphaShape::EnclosedRegionAt(const Eigen::Vector2d& point) {
  if (!impl_->HasFaces() || impl_->enclosed_regions == 0) return -1;
  return Impl::FilledRegion(impl_->shape, impl_->Locate(point));
}

int SiteAlphaShape::EnclosedRegionAt(const Eigen::Vector2d& point, int vertex) {
  Impl& impl = *impl_;
  if (!impl.HasFaces() || impl.enclosed_regions == 0) return -1;
  const Impl::Probe probe = impl.ProbeAt(point, impl.VertexFace(vertex));
  return impl.Apply(probe, point);
}

std::vector<int> SiteAlphaShape::EnclosedRegionsAt(const PointList& points,
                                                   const std::function<bool(int)>& wanted) {
  Impl& impl = *impl_;
  std::vector<int> regions(points.size(), -1);
  if (!impl.HasFaces() || impl.enclosed_regions == 0) return regions;
  impl.VertexFace(-1);  // built before the ranges read it
  // Each range probes its points from their own faces (const walks) and
  // keeps, in order, what the state between calls needs: the walks put off
  // and those that depend on the last hint, after the last face found
  // before them (earlier ones are overwritten by it). Replayed in order
  // below, they leave the answers and `hint` as the calls one by one do.
  struct Event {
    int index;
    Impl::Kind kind;
    Face face;
  };
  const auto events = MapRanges<std::vector<Event>>(
      points.size(), kMinPointsPerRange, [&](size_t begin, size_t end) {
        std::vector<Event> kept;
        Face last_face;
        for (size_t i = begin; i < end; ++i) {
          if (i + kAhead < end) impl.PrefetchVertexFace(static_cast<int>(i + kAhead));
          if (!wanted(static_cast<int>(i))) continue;
          const Impl::Probe probe = impl.ProbeAt(points[i], impl.VertexFace(static_cast<int>(i)));
          if (probe.kind == Impl::Kind::kFace) {
            last_face = probe.face;
            regions[i] = probe.region;
            continue;
          }
          if (last_face != Face()) kept.push_back({-1, Impl::Kind::kFace, last_face});
          last_face = Face();
          if (probe.kind == Impl::Kind::kAgree) regions[i] = probe.region;
          kept.push_back({static_cast<int>(i), probe.kind, Face()});
        }
        if (last_face != Face()) kept.push_back({-1, Impl::Kind::kFace, last_face});
        return kept;
      });
  for (const std::vector<Event>& range : events) {
    for (const Event& event : range) {
      const Eigen::Vector2d& point = event.index >= 0 ? points[event.index] : Eigen::Vector2d();
      const int region = impl.Apply({event.kind, -1, event.face}, point);
      if (event.kind == Impl::Kind::kWalk) regions[event.index] = region;
    }
  }
  return regions;
}

proto::Polygon SiteAlphaShape::EnclosedRegionOutline(int region) {
  Impl& impl = *impl_;
  if (!impl.HasFaces() || region < 0 || region >= impl.enclosed_regions) return proto::Polygon();
  const auto rings = impl.RegionRings(&FaceInfo::filled_region, region);
  const auto found = rings.find(region);
  if (found == rings.end()) return proto::Polygon();
  return Impl::ToPolygon(found->second, /*with_holes=*/false);
}

std::map<int, proto::Polygon> SiteAlphaShape::EnclosedRegionOutlines(const std::set<int>& regions) {
  Impl& impl = *impl_;
  std::map<int, proto::Polygon> outlines;
  if (!impl.HasFaces() || regions.empty()) return outlines;
  // A region's rings do not depend on the others' (each walk marks its own
  // region's faces only), so one pass gives what EnclosedRegionOutline gives.
  const auto rings = impl.RegionRings(&FaceInfo::filled_region);
  for (const int region : regions) {
    const auto found = rings.find(region);
    outlines[region] =
        found == rings.end() ? proto::Polygon() : Impl::ToPolygon(found->second, false);
  }
  return outlines;
}

int SiteAlphaShape::DetectRooms(
    const std::function<bool(const Eigen::Vector2d&)>& inside_boundary) {
  Impl& impl = *impl_;
  impl.room_ids.clear();
  impl.room_areas.clear();
  impl.areas_valid = false;
  if (!impl.HasFaces()) return 0;
  // LabelRegions' walk with the member test asked once per face, first, over
  // ranges of the faces in parallel (-3: a room's, -1: no room), and each
  // face's area added to its room as the seed loop passes it: its label is
  // final by then (set by an earlier walk, or now as a seed, or never), so
  // the sums run in face order as RoomAreas'.
  auto& shape = impl.shape;
  impl.ForEachFaceRange([&](Delaunay::All_faces_iterator face, size_t count) {
    for (; count > 0; --count, ++face) {
      if (shape.is_infinite(face)) continue;
      face->info().room = !Impl::Interior(face) && inside_boundary(Centroid(face)) ? -3 : -1;
    }
  });
  auto member = [](const Face& face) { return face->info().room == -3; };
  int count = 0;
  std::vector<Face> stack;
  for (Face seed : shape.finite_face_handles()) {
    if (seed->info().room < 0 && member(seed)) {
      seed->info().room = count;
      impl.room_areas.push_back(0.0);
      stack.push_back(seed);
      Impl::Spread(&stack, [&](const Face& face, int i, const Face& next) {
        if (shape.is_infinite(next) || next->info().room >= 0) return false;
        if (Impl::InComplex(face, i) || !member(next)) return false;
        next->info().room = count;
        return true;
      });
      ++count;
    }
    if (seed->info().room < 0) {
      seed->info().room = -1;
    } else {
      impl.room_areas[seed->info().room] += TriangleArea(seed);
    }
  }
  impl.room_ids.resize(count);
  for (int room = 0; room < count; ++room) impl.room_ids[room] = room;
  impl.areas_valid = true;
  return count;
}

std::vector<double> SiteAlphaShape::RoomAreas() {
  Impl& impl = *impl_;
  if (impl.areas_valid) return impl.room_areas;
  std::vector<double> areas;
  if (!impl.HasFaces()) return areas;
  for (Face face : impl.shape.finite_face_handles()) {
    const int room = impl.RoomId(face);
    if (room < 0) continue;
    if (room >= static_cast<int>(areas.size())) areas.resize(room + 1, 0.0);
    areas[room] += TriangleArea(face);
  }
  return areas;
}

int SiteAlphaShape::RoomAt(const Eigen::Vector2d& point) {
  if (!impl_->HasFaces()) return -1;
  const Face face = impl_->Locate(point);
  return impl_->shape.is_infinite(face) ? -1 : impl_->RoomId(face);
}

void SiteAlphaShape::RenumberRooms(const std::vector<int>& new_ids) {
  Impl& impl = *impl_;
  impl.areas_valid = false;
  for (int& room : impl.room_ids) {
    if (room >= 0) room = room < static_cast<int>(new_ids.size()) ? new_ids[room] : -1;
  }
}

std::vector<proto::Polygon> SiteAlphaShape::RoomOutlines() {
  std::vector<proto::Polygon> outlines;
  if (!impl_->HasFaces()) return outlines;
  // The faces take their rooms' ids now (the labels stay ids from here on).
  // (A renumbering may have given ids past the labels: the identity covers
  // them all.)
  int ids = 0;
  for (Face face : impl_->shape.finite_face_handles()) {
    face->info().room = impl_->RoomId(face);
    ids = std::max(ids, face->info().room + 1);
  }
  impl_->room_ids.resize(ids);
  for (int room = 0; room < ids; ++room) impl_->room_ids[room] = room;
  const auto rings = impl_->RegionRings(&FaceInfo::room);
  for (const auto& [room, room_rings] : rings) {
    if (room >= static_cast<int>(outlines.size())) outlines.resize(room + 1);
    outlines[room] = Impl::ToPolygon(room_rings, /*with_holes=*/true);
  }
  return outlines;
}

}  // namespace areagraph

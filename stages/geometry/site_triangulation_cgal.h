#pragma once

// The CGAL type behind SiteTriangulation. Heavy templates: include only from
// the .cc files that run CGAL on it (voronoi_builder.cc, site_alpha_shape.cc,
// site_triangulation.cc), never from a header.

#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_data_structure_2.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>
#include <emmintrin.h>

#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "stages/geometry/site_triangulation.h"

namespace areagraph {

// What the users of a site triangulation write on its faces: the Voronoi
// builder's face number, and SiteAlphaShape's labels (`interior` and
// `in_complex`, bit i for edge i, are the face's and its edges' places in the
// alpha complex; `walked` marks boundary edges already put in a ring).
struct SiteFaceInfo {
  int number = -1;
  int filled_region = -1;
  int room = -1;
  bool outside = false;
  bool interior = false;
  unsigned char in_complex = 0;
  unsigned char walked = 0;
};

namespace site_cgal {
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_2;

// The in-circle test of Kernel, exact in 64-bit integers when all four points
// are cell centres (c + 0.5, r + 0.5) with |c|, |r| below 8192. Both are
// exact, so the signs and with them the triangulation are Kernel's; but most
// obstacle sites are cell centres, and on that grid every fourth test or so
// is co-circular, which Kernel settles only in its exact number type (a
// tenth of ag-cut's instructions, lab_e, issue 14's fourteenth pass).
struct GridSideOfOrientedCircle {
  using result_type = CGAL::Oriented_side;
  Kernel::Side_of_oriented_circle_2 general;
  CGAL::Oriented_side operator()(const Point& p, const Point& q, const Point& r,
                                 const Point& t) const {
    if (!OnGrid(p, q, r, t)) return general(p, q, r, t);
    // Kernel's determinant (side_of_oriented_circleC2), p moved to the origin.
    // The differences of cell centres are whole numbers below 2^14, so the
    // four entries are exact in double (below 2^29) and their products in
    // 64-bit integers (below 2^59).
    const double qpx = q.x() - p.x(), qpy = q.y() - p.y();
    const double rpx = r.x() - p.x(), rpy = r.y() - p.y();
    const double tpx = t.x() - p.x(), tpy = t.y() - p.y();
    const double tqx = t.x() - q.x(), tqy = t.y() - q.y();
    const double rqx = r.x() - q.x(), rqy = r.y() - q.y();
    const auto a = static_cast<int64_t>(qpx * tpy - qpy * tpx);
    const auto b = static_cast<int64_t>(tpx * tqx + tpy * tqy);
    const auto c = static_cast<int64_t>(qpx * rpy - qpy * rpx);
    const auto d = static_cast<int64_t>(rpx * rqx + rpy * rqy);
    const int64_t ad = a * d, cb = c * b;
    return ad > cb   ? CGAL::ON_POSITIVE_SIDE
           : ad < cb ? CGAL::ON_NEGATIVE_SIDE
                     : CGAL::ON_ORIENTED_BOUNDARY;
  }
  // Whether each of the four points is a cell centre (c + 0.5, r + 0.5) with
  // |c|, |r| <= 8191; two coordinates at a time.
  static bool OnGrid(const Point& p, const Point& q, const Point& r, const Point& t) {
    const __m128d half = _mm_set1_pd(0.5), limit = _mm_set1_pd(8191.0);
    const __m128d magnitude = _mm_castsi128_pd(_mm_set1_epi64x(0x7fffffffffffffffLL));
    __m128d ok = _mm_castsi128_pd(_mm_set1_epi32(-1));
    for (const Point* point : {&p, &q, &r, &t}) {
      const __m128d v = _mm_set_pd(point->y(), point->x());
      const __m128d shifted = _mm_sub_pd(v, half);
      const __m128d whole = _mm_cvtepi32_pd(_mm_cvttpd_epi32(shifted));
      ok = _mm_and_pd(ok, _mm_cmpeq_pd(_mm_add_pd(whole, half), v));
      ok = _mm_and_pd(ok, _mm_cmple_pd(_mm_and_pd(shifted, magnitude), limit));
    }
    return _mm_movemask_pd(ok) == 3;
  }
};

// Kernel with that in-circle test (Delaunay_triangulation_2's only use of it).
struct Traits : Kernel {
  using Side_of_oriented_circle_2 = GridSideOfOrientedCircle;
  Side_of_oriented_circle_2 side_of_oriented_circle_2_object() const {
    return {Kernel::side_of_oriented_circle_2_object()};
  }
};

}  // namespace site_cgal
}  // namespace areagraph

// Traits locates as Kernel does (a straight walk first, then the exact one):
// the face a walk ends in decides where a point on an edge goes, so another
// walk would build another order of the same faces.
template <>
struct CGAL::Triangulation_structural_filtering_traits<areagraph::site_cgal::Traits>
    : CGAL::Triangulation_structural_filtering_traits<areagraph::site_cgal::Kernel> {};

namespace areagraph {
namespace site_cgal {
// Vertices carry their index in the site list (set by TriangulateIndexedSites).
using VertexBase = CGAL::Triangulation_vertex_base_with_info_2<int, Kernel>;
using FaceBase = CGAL::Triangulation_face_base_with_info_2<SiteFaceInfo, Kernel>;
using Tds = CGAL::Triangulation_data_structure_2<VertexBase, FaceBase>;
using Delaunay = CGAL::Delaunay_triangulation_2<Traits, Tds>;
}  // namespace site_cgal

struct SiteTriangulation {
  site_cgal::Delaunay dt;
};

}  // namespace areagraph

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
#include <initializer_list>
#include <vector>

#include "stages/geometry/site_triangulation.h"

namespace areagraph {

// What the users of a site triangulation write on its faces: the Voronoi
// builder's face number (once the diagram is built, the Voronoi vertex at
// the face's circumcentre, from which SiteAlphaShape::EnclosedRegionAt walks),
// and SiteAlphaShape's labels (`interior` and
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

// Epick with an integer in-circle test for sites on the half-pixel grid
// (cell centres): the same exact sign as Epick's filtered predicate, without
// its interval-arithmetic fallback, which every co-circular quadruple of grid
// points (most of a map's) takes. Every other predicate and construction is
// Epick's. `on_half_grid` holds only when every point ever tested is a
// multiple of 0.5 within +-kHalfGridLimit: set it only for a triangulation of
// such sites (in-circle tests see its vertices and inserted points only).
// Without it, each call checks its own four points (MixedHalfGrid): cut's
// sites are cell centres but for the few hundred that close doors and gaps
// along lines, and its grid quadruples would all take Epick's exact fallback.
struct Traits : Kernel {
  static constexpr double kHalfGridLimit = 33554432.0;  // 2^25: int64 minors, int128 products
  bool on_half_grid = false;

  Traits() = default;
  explicit Traits(bool half_grid) : on_half_grid(half_grid) {}

  struct Side_of_oriented_circle_2 {
    using result_type = CGAL::Oriented_side;
    bool on_half_grid;
    __attribute__((always_inline)) CGAL::Oriented_side operator()(const Point& p, const Point& q,
                                                                  const Point& r,
                                                                  const Point& t) const {
      // All on the half grid: exact in integers (as cheap as the filter below
      // and never in doubt).
      if (on_half_grid) return OnHalfGridSign(p, q, r, t);
      // Else Epick's determinant (side_of_oriented_circleC2) in double first:
      // its sign is certain when it is farther from 0 than the rounding can
      // move it, most calls (not the co-circular ones).
      const double qpx = q.x() - p.x(), qpy = q.y() - p.y();
      const double rpx = r.x() - p.x(), rpy = r.y() - p.y();
      const double tpx = t.x() - p.x(), tpy = t.y() - p.y();
      const double tqx = t.x() - q.x(), tqy = t.y() - q.y();
      const double rqx = r.x() - q.x(), rqy = r.y() - q.y();
      const double a = qpx * tpy - qpy * tpx, b = tpx * tqx + tpy * tqy;
      const double c = qpx * rpy - qpy * rpx, d = rpx * rqx + rpy * rqy;
      const double det = a * d - b * c;
      const double bound = MaxMagnitude({qpx, qpy, rpx, rpy, tpx, tpy, tqx, tqy, rqx, rqy});
      // With every difference at most `bound` in magnitude, the rounding
      // error of `det` is below 80 u bound^4 (u = 2^-53: each difference and
      // operation off by at most u relatively; the entries, at most 2 bound^2,
      // are off by 8 u bound^2 each). Outside this range of `bound` the scale
      // could overflow or underflow, and a NaN fails both comparisons: the
      // exact tests decide.
      if (bound >= 1e-60 && bound <= 1e60) {
        const double squared = bound * bound;
        const double error = squared * squared * (128.0 / 9007199254740992.0);
        if (det > error) return CGAL::ON_POSITIVE_SIDE;
        if (det < -error) return CGAL::ON_NEGATIVE_SIDE;
      }
      return Exact(p, q, r, t, a, b, c, d);
    }

    // The exact sign where the double determinant (entries a to d) is too
    // close to 0; out of line, so that the common path stays small.
    __attribute__((noinline)) static CGAL::Oriented_side Exact(const Point& p, const Point& q,
                                                               const Point& r, const Point& t,
                                                               double a, double b, double c,
                                                               double d) {
      if (NearOnHalfGrid(p, q, r, t)) {
        // Differences of multiples of 0.5 below 2^14 are exact, so are the
        // four entries (multiples of 0.25 below 2^29); times 4 they are whole
        // and their products exact in 64-bit integers.
        const auto ad = static_cast<int64_t>(4 * a) * static_cast<int64_t>(4 * d);
        const auto bc = static_cast<int64_t>(4 * b) * static_cast<int64_t>(4 * c);
        return ad > bc ? CGAL::ON_POSITIVE_SIDE
                       : (ad < bc ? CGAL::ON_NEGATIVE_SIDE : CGAL::ON_ORIENTED_BOUNDARY);
      }
      return Kernel().side_of_oriented_circle_2_object()(p, q, r, t);
    }

    // The largest magnitude of `values` (a NaN may be skipped: it makes the
    // determinant NaN anyway).
    static double MaxMagnitude(std::initializer_list<double> values) {
      double largest = 0;
      for (const double value : values) largest = std::max(largest, std::abs(value));
      return largest;
    }

    // The exact sign for points on the half grid within +-kHalfGridLimit:
    // the determinant on doubled, integral coordinates (scaled by 2^4).
    static CGAL::Oriented_side OnHalfGridSign(const Point& p, const Point& q, const Point& r,
                                              const Point& t) {
      auto twice = [](double v) { return static_cast<int64_t>(2 * v); };
      const int64_t px = twice(p.x()), py = twice(p.y());
      const int64_t qpx = twice(q.x()) - px, qpy = twice(q.y()) - py;
      const int64_t rpx = twice(r.x()) - px, rpy = twice(r.y()) - py;
      const int64_t tpx = twice(t.x()) - px, tpy = twice(t.y()) - py;
      const int64_t a = qpx * tpy - qpy * tpx;
      const int64_t b = tpx * (tpx - qpx) + tpy * (tpy - qpy);
      const int64_t c = qpx * rpy - qpy * rpx;
      const int64_t d = rpx * (rpx - qpx) + rpy * (rpy - qpy);
      const __int128 left = static_cast<__int128>(a) * d, right = static_cast<__int128>(b) * c;
      return left > right ? CGAL::ON_POSITIVE_SIDE
                          : (left < right ? CGAL::ON_NEGATIVE_SIDE : CGAL::ON_ORIENTED_BOUNDARY);
    }

    // Whether every coordinate is a multiple of 0.5 with magnitude at most
    // kMixedLimit; two coordinates at a time (NaN fails the comparisons).
    static constexpr double kMixedLimit = 8191.0;
    static bool NearOnHalfGrid(const Point& p, const Point& q, const Point& r, const Point& t) {
      const __m128d two = _mm_set1_pd(2.0), limit = _mm_set1_pd(2 * kMixedLimit);
      const __m128d magnitude = _mm_castsi128_pd(_mm_set1_epi64x(0x7fffffffffffffffLL));
      __m128d ok = _mm_castsi128_pd(_mm_set1_epi32(-1));
      for (const Point* point : {&p, &q, &r, &t}) {
        const __m128d twice = _mm_mul_pd(_mm_set_pd(point->y(), point->x()), two);
        const __m128d whole = _mm_cvtepi32_pd(_mm_cvttpd_epi32(twice));
        ok = _mm_and_pd(ok, _mm_cmpeq_pd(whole, twice));
        ok = _mm_and_pd(ok, _mm_cmple_pd(_mm_and_pd(twice, magnitude), limit));
      }
      return _mm_movemask_pd(ok) == 3;
    }
  };
  Side_of_oriented_circle_2 side_of_oriented_circle_2_object() const { return {on_half_grid}; }
};

}  // namespace site_cgal
}  // namespace areagraph

// Locate as with Epick (an inexact walk, then the exact one from where it
// stopped): which face a walk returns for a point on an edge depends on it.
template <>
struct CGAL::Triangulation_structural_filtering_traits<areagraph::site_cgal::Traits> {
  using Use_structural_filtering_tag = CGAL::Tag_true;
};

namespace areagraph {
namespace site_cgal {
// Vertices carry their index in the site list (set by TriangulateIndexedSites).
using VertexBase = CGAL::Triangulation_vertex_base_with_info_2<int, Traits>;
using FaceBase = CGAL::Triangulation_face_base_with_info_2<SiteFaceInfo, Traits>;
using Tds = CGAL::Triangulation_data_structure_2<VertexBase, FaceBase>;
using Delaunay = CGAL::Delaunay_triangulation_2<Traits, Tds>;
}  // namespace site_cgal

struct SiteTriangulation {
  explicit SiteTriangulation(bool on_half_grid) : dt(site_cgal::Traits(on_half_grid)) {}
  site_cgal::Delaunay dt;
};

}  // namespace areagraph

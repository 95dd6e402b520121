#include "stages/geometry/site_triangulation.h"

#include <cmath>
#include <mutex>
#include <utility>

#include "stages/geometry/site_triangulation_cgal.h"
#include "stages/geometry/spatial_sort_on_pool.h"

namespace areagraph {
namespace {

// The one kept triangulation of this process and the sites it was made from.
struct KeptTriangulation {
  std::mutex mutex;
  SiteTriangulationPtr triangulation;
  std::vector<Eigen::Vector2d> sites;
};

KeptTriangulation& Kept() {
  static KeptTriangulation kept;
  return kept;
}

// Whether every site is a multiple of 0.5 within the integer in-circle
// test's range (site_cgal::Traits).
bool OnHalfGrid(const std::vector<Eigen::Vector2d>& sites) {
  for (const Eigen::Vector2d& site : sites) {
    for (const double value : {site.x(), site.y()}) {
      const double twice = 2 * value;
      if (!(std::abs(value) <= site_cgal::Traits::kHalfGridLimit) || twice != std::floor(twice)) {
        return false;
      }
    }
  }
  return true;
}

std::vector<site_cgal::Point> KernelPoints(const std::vector<Eigen::Vector2d>& sites) {
  std::vector<site_cgal::Point> points;
  points.reserve(sites.size());
  for (const Eigen::Vector2d& site : sites) points.emplace_back(site.x(), site.y());
  return points;
}

// One spatially sorted range insert (as Alpha_shape_2's constructor does):
// Delaunay_triangulation_2::insert(first, last) of CGAL 5.5 step for step,
// the spatial sort's last three quarters on the pool while the first is
// inserted (the same order).
SiteTriangulationPtr TriangulatePoints(std::vector<site_cgal::Point> points, bool on_half_grid) {
  SiteTriangulationPtr triangulation(new SiteTriangulation(on_half_grid));
  site_cgal::Delaunay& dt = triangulation->dt;
  site_cgal::Delaunay::Face_handle hint;
  using Iterator = std::vector<site_cgal::Point>::iterator;
  SpatialSortThenInsert(points.begin(), points.end(), dt.geom_traits(),
                        [&](Iterator first, Iterator last) {
                          for (; first != last; ++first) hint = dt.insert(*first, hint)->face();
                        });
  return triangulation;
}

}  // namespace

void SiteTriangulationDeleter::operator()(SiteTriangulation* triangulation) const {
  delete triangulation;
}

SiteTriangulationPtr CopySiteTriangulation(const SiteTriangulation& triangulation) {
  return SiteTriangulationPtr(new SiteTriangulation(triangulation));
}

size_t SiteTriangulationBytes(const SiteTriangulation& triangulation) {
  const auto& tds = triangulation.dt.tds();
  return tds.number_of_vertices() * sizeof(site_cgal::Tds::Vertex) +
         tds.number_of_faces() * sizeof(site_cgal::Tds::Face);
}

// The range insert of (point, index) pairs, Delaunay_triangulation_2's
// insert_with_info of CGAL 5.5 step for step, the spatial sort of the
// indices as in TriangulatePoints (the same order).
SiteTriangulationPtr TriangulateIndexedSites(const std::vector<Eigen::Vector2d>& sites) {
  const std::vector<site_cgal::Point> points = KernelPoints(sites);
  std::vector<size_t> order(points.size());
  for (size_t i = 0; i < order.size(); ++i) order[i] = i;
  SiteTriangulationPtr triangulation(new SiteTriangulation(OnHalfGrid(sites)));
  site_cgal::Delaunay& dt = triangulation->dt;
  using PointMap = CGAL::Pointer_property_map<site_cgal::Point>::const_type;
  using SortTraits = CGAL::Spatial_sort_traits_adapter_2<site_cgal::Traits, PointMap>;
  site_cgal::Delaunay::Face_handle hint;
  using Iterator = std::vector<size_t>::iterator;
  SpatialSortThenInsert(
      order.begin(), order.end(), SortTraits(CGAL::make_property_map(points), dt.geom_traits()),
      [&](Iterator first, Iterator last) {
        for (; first != last; ++first) {
          const site_cgal::Delaunay::Vertex_handle vertex = dt.insert(points[*first], hint);
          if (vertex != site_cgal::Delaunay::Vertex_handle()) {
            vertex->info() = static_cast<int>(*first);
            hint = vertex->face();
          }
        }
      });
  return triangulation;
}

SiteTriangulationPtr TriangulateSites(const std::vector<Eigen::Vector2d>& sites) {
  return TriangulatePoints(KernelPoints(sites), OnHalfGrid(sites));
}

SiteTriangulationPtr TriangulateSites(std::vector<Eigen::Vector2d>&& sites) {
  std::vector<site_cgal::Point> points = KernelPoints(sites);
  const bool on_half_grid = OnHalfGrid(sites);
  std::vector<Eigen::Vector2d>().swap(sites);
  return TriangulatePoints(std::move(points), on_half_grid);
}

void KeepSiteTriangulation(SiteTriangulationPtr triangulation, std::vector<Eigen::Vector2d> sites) {
  KeptTriangulation& kept = Kept();
  const std::lock_guard<std::mutex> lock(kept.mutex);
  kept.triangulation.reset();
  kept.sites.clear();
  kept.sites.shrink_to_fit();
  if (triangulation == nullptr) return;
  kept.triangulation = std::move(triangulation);
  kept.sites = std::move(sites);
}

SiteTriangulationPtr TakeSiteTriangulation(const std::vector<Eigen::Vector2d>& sites) {
  KeptTriangulation& kept = Kept();
  const std::lock_guard<std::mutex> lock(kept.mutex);
  SiteTriangulationPtr taken = std::move(kept.triangulation);
  const bool same = kept.sites == sites;
  std::vector<Eigen::Vector2d>().swap(kept.sites);
  if (!same) taken.reset();
  return taken;
}

void DropSiteTriangulation() {
  KeptTriangulation& kept = Kept();
  const std::lock_guard<std::mutex> lock(kept.mutex);
  kept.triangulation.reset();
  std::vector<Eigen::Vector2d>().swap(kept.sites);
}

}  // namespace areagraph

#include "stages/clean/outlier_points.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/property_map.h>
#include <CGAL/remove_outliers.h>

#include <algorithm>
#include <cmath>
#include <utility>

namespace areagraph {

std::vector<int> FindOutlierPoints(const std::vector<Eigen::Vector2d>& points, int k,
                                   double percent, double min_score) {
  using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
  using IndexedPoint = std::pair<Kernel::Point_3, int>;
  if (points.empty() || percent <= 0) return {};
  std::vector<IndexedPoint> indexed;
  indexed.reserve(points.size());
  for (size_t i = 0; i < points.size(); ++i) {
    indexed.emplace_back(Kernel::Point_3(points[i].x(), points[i].y(), 0.0), int(i));
  }
  const auto first_outlier = CGAL::remove_outliers<CGAL::Sequential_tag>(
      indexed, static_cast<unsigned int>(k),
      CGAL::parameters::point_map(CGAL::First_of_pair_property_map<IndexedPoint>())
          .threshold_percent(percent)
          .threshold_distance(std::sqrt(min_score)));
  std::vector<int> outliers;
  for (auto it = first_outlier; it != indexed.end(); ++it) outliers.push_back(it->second);
  std::sort(outliers.begin(), outliers.end());
  return outliers;
}

}  // namespace areagraph

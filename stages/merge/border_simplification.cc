// The one translation unit of ag-merge that compiles CGAL's constrained
// triangulation and polyline simplification.
#include "stages/merge/border_simplification.h"

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Constrained_triangulation_plus_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polyline_simplification_2/simplify.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace areagraph {
namespace {

namespace PS = CGAL::Polyline_simplification_2;
// Exact predicates keep the triangulation of the (very degenerate) cell
// corners consistent; the chains never cross, so nothing is constructed.
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
// What each vertex carries into its cost.
struct VertexCostInfo {
  // Scales the vertex's cost to the global tolerance: (largest tolerance /
  // its chain's tolerance)^2, infinite for a chain that keeps every point.
  double factor = 1;
  // A tiny amount, unique per vertex and growing in input order, taken off
  // its cost. CGAL's queue orders by cost alone and fills it in an order
  // that depends on memory addresses, so equal costs (common on the pixel
  // grid) would otherwise be simplified in a different order from run to
  // run, and give different outlines.
  double tie_break = 0;
};
using VertexBase =
    PS::Vertex_base_2<Kernel, CGAL::Triangulation_vertex_base_with_info_2<VertexCostInfo, Kernel>>;
// Tie-break step per vertex (square pixels): a million vertices move costs by
// 1e-6 px^2 at most.
constexpr double kTieBreakStep = 1e-12;
using FaceBase = CGAL::Constrained_triangulation_face_base_2<Kernel>;
using Tds = CGAL::Triangulation_data_structure_2<VertexBase, FaceBase>;
using Cdt = CGAL::Constrained_Delaunay_triangulation_2<Kernel, Tds, CGAL::Exact_predicates_tag>;
using ConstrainedTriangulation = CGAL::Constrained_triangulation_plus_2<Cdt>;

// The squared distance cost scaled by the vertex's factor: one global
// threshold then applies each chain's own tolerance.
class ScaledSquaredDistanceCost {
 public:
  boost::optional<double> operator()(
      const ConstrainedTriangulation& triangulation,
      ConstrainedTriangulation::Vertices_in_constraint_iterator vertex) const {
    const VertexCostInfo& info = (*vertex)->info();
    if (!std::isfinite(info.factor)) return boost::none;  // never removed
    const boost::optional<double> cost = distance_(triangulation, vertex);
    if (!cost) return cost;
    return *cost * info.factor - info.tie_break;
  }

 private:
  PS::Squared_distance_cost distance_;
};

}  // namespace

std::vector<PointList> SimplifyBorders(const std::vector<PointList>& chains,
                                       const std::vector<double>& tolerance_px) {
  const double largest =
      tolerance_px.empty() ? 0 : *std::max_element(tolerance_px.begin(), tolerance_px.end());
  if (!(largest > 0)) return chains;
  ConstrainedTriangulation triangulation;
  std::vector<ConstrainedTriangulation::Constraint_id> ids;
  ids.reserve(chains.size());
  std::vector<Kernel::Point_2> points;
  int64_t order = 0;
  for (size_t i = 0; i < chains.size(); ++i) {
    points.clear();
    for (const Eigen::Vector2d& p : chains[i]) points.emplace_back(p.x(), p.y());
    ids.push_back(triangulation.insert_constraint(points.begin(), points.end()));
    const double ratio = tolerance_px[i] > 0 ? largest / tolerance_px[i] : INFINITY;
    for (auto it = triangulation.vertices_in_constraint_begin(ids.back());
         it != triangulation.vertices_in_constraint_end(ids.back()); ++it) {
      (*it)->info() = {ratio * ratio, kTieBreakStep * static_cast<double>(++order)};
    }
  }
  PS::simplify(triangulation, ScaledSquaredDistanceCost(),
               PS::Stop_above_cost_threshold(largest * largest), /*remove_points=*/false);
  std::vector<PointList> simplified(chains.size());
  for (size_t i = 0; i < chains.size(); ++i) {
    for (auto it = triangulation.vertices_in_constraint_begin(ids[i]);
         it != triangulation.vertices_in_constraint_end(ids[i]); ++it) {
      simplified[i].emplace_back((*it)->point().x(), (*it)->point().y());
    }
  }
  return simplified;
}

}  // namespace areagraph

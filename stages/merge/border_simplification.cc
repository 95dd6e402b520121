// The one translation unit of ag-merge that compiles CGAL's constrained
// triangulation and polyline simplification.
#include "stages/merge/border_simplification.h"

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Constrained_triangulation_plus_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polyline_simplification_2/simplify.h>

namespace areagraph {
namespace {

namespace PS = CGAL::Polyline_simplification_2;
// Exact predicates keep the triangulation of the (very degenerate) cell
// corners consistent; the chains never cross, so nothing is constructed.
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using VertexBase = PS::Vertex_base_2<Kernel>;
using FaceBase = CGAL::Constrained_triangulation_face_base_2<Kernel>;
using Tds = CGAL::Triangulation_data_structure_2<VertexBase, FaceBase>;
using Cdt = CGAL::Constrained_Delaunay_triangulation_2<Kernel, Tds, CGAL::Exact_predicates_tag>;
using ConstrainedTriangulation = CGAL::Constrained_triangulation_plus_2<Cdt>;

}  // namespace

std::vector<PointList> SimplifyBorders(const std::vector<PointList>& chains, double tolerance_px) {
  if (!(tolerance_px > 0)) return chains;
  ConstrainedTriangulation triangulation;
  std::vector<ConstrainedTriangulation::Constraint_id> ids;
  ids.reserve(chains.size());
  std::vector<Kernel::Point_2> points;
  for (const PointList& chain : chains) {
    points.clear();
    for (const Eigen::Vector2d& p : chain) points.emplace_back(p.x(), p.y());
    ids.push_back(triangulation.insert_constraint(points.begin(), points.end()));
  }
  PS::simplify(triangulation, PS::Squared_distance_cost(),
               PS::Stop_above_cost_threshold(tolerance_px * tolerance_px));
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

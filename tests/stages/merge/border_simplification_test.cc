// SimplifyBorders against CGAL's Polyline_simplification_2 on one
// constrained triangulation, the way ag-merge simplified the borders up to
// merge 11 (kept here as the reference): the same points must remain, chain
// for chain, on random label images and on map-like ones.
#include "stages/merge/border_simplification.h"

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Constrained_triangulation_plus_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polyline_simplification_2/simplify.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <opencv2/imgproc.hpp>
#include <random>

#include "stages/merge/planar_partition.h"

namespace areagraph {
namespace {

namespace PS = CGAL::Polyline_simplification_2;
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
struct VertexCostInfo {
  double factor = 1;
  double tie_break = 0;
};
using VertexBase =
    PS::Vertex_base_2<Kernel, CGAL::Triangulation_vertex_base_with_info_2<VertexCostInfo, Kernel>>;
using FaceBase = CGAL::Constrained_triangulation_face_base_2<Kernel>;
using Tds = CGAL::Triangulation_data_structure_2<VertexBase, FaceBase>;
using Cdt = CGAL::Constrained_Delaunay_triangulation_2<Kernel, Tds, CGAL::Exact_predicates_tag>;
using ConstrainedTriangulation = CGAL::Constrained_triangulation_plus_2<Cdt>;

class ScaledSquaredDistanceCost {
 public:
  boost::optional<double> operator()(
      const ConstrainedTriangulation& triangulation,
      ConstrainedTriangulation::Vertices_in_constraint_iterator vertex) const {
    const VertexCostInfo& info = (*vertex)->info();
    if (!std::isfinite(info.factor)) return boost::none;
    const boost::optional<double> cost = distance_(triangulation, vertex);
    if (!cost) return cost;
    return *cost * info.factor - info.tie_break;
  }

 private:
  PS::Squared_distance_cost distance_;
};

// merge 11's SimplifyBorders, as it was.
std::vector<PointList> CgalSimplifyBorders(const std::vector<PointList>& chains,
                                           const std::vector<double>& tolerance_px) {
  const double largest =
      tolerance_px.empty() ? 0 : *std::max_element(tolerance_px.begin(), tolerance_px.end());
  if (!(largest > 0)) return chains;
  ConstrainedTriangulation triangulation;
  std::vector<ConstrainedTriangulation::Constraint_id> ids;
  std::vector<Kernel::Point_2> points;
  int64_t order = 0;
  for (size_t i = 0; i < chains.size(); ++i) {
    points.clear();
    for (const Eigen::Vector2d& p : chains[i]) points.emplace_back(p.x(), p.y());
    ids.push_back(triangulation.insert_constraint(points.begin(), points.end()));
    const double ratio = tolerance_px[i] > 0 ? largest / tolerance_px[i] : INFINITY;
    for (auto it = triangulation.vertices_in_constraint_begin(ids.back());
         it != triangulation.vertices_in_constraint_end(ids.back()); ++it) {
      (*it)->info() = {ratio * ratio, 1e-12 * static_cast<double>(++order)};
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

// Blobs of labels 0..label_count on a grid: random discs and bars, so that
// borders run straight, diagonal and curved, with junctions and holes.
cv::Mat RandomLabels(std::mt19937* random, int size, int label_count) {
  cv::Mat labels(size, size, CV_32S, cv::Scalar(1));
  std::uniform_int_distribution<int> at(0, size - 1), label(0, label_count), radius(1, size / 5);
  std::uniform_real_distribution<double> angle(0, M_PI);
  for (int k = 0; k < 14; ++k) {
    const cv::Point centre(at(*random), at(*random));
    if (k % 2 == 0) {
      cv::circle(labels, centre, radius(*random), cv::Scalar(label(*random)), cv::FILLED,
                 cv::LINE_8);
    } else {
      const double a = angle(*random);
      const int length = radius(*random) * 2;
      const cv::Point end(centre.x + static_cast<int>(length * std::cos(a)),
                          centre.y + static_cast<int>(length * std::sin(a)));
      cv::line(labels, centre, end, cv::Scalar(label(*random)), 1 + k % 3, cv::LINE_8);
    }
  }
  return labels;
}

void ExpectSameAsCgal(const cv::Mat& labels, int label_count, std::mt19937* random,
                      const std::string& what) {
  const PlanarPartition partition = BuildPlanarPartition(labels, label_count);
  const std::vector<PointList> chains = ChainPoints(partition);
  std::uniform_int_distribution<int> pick(0, 9);
  for (const double tolerance : {0.5, 1.5, 3.0}) {
    std::vector<double> tolerances(chains.size(), tolerance);
    // Some chains with their own, finer tolerances, and some that keep all.
    for (double& t : tolerances) {
      const int p = pick(*random);
      if (p == 0) t = 0;
      if (p == 1) t = 0.5;
    }
    const std::vector<PointList> expected = CgalSimplifyBorders(chains, tolerances);
    const std::vector<PointList> simplified = SimplifyBorders(chains, tolerances);
    ASSERT_EQ(simplified.size(), expected.size()) << what;
    for (size_t i = 0; i < expected.size(); ++i) {
      ASSERT_EQ(simplified[i], expected[i])
          << what << ", tolerance " << tolerance << ", chain " << i;
    }
  }
}

TEST(BorderSimplificationTest, KeepsTheSamePointsAsCgalOnRandomLabels) {
  std::mt19937 random(14);
  for (int map = 0; map < 60; ++map) {
    const int size = 20 + 10 * (map % 8);
    const int label_count = 2 + map % 6;
    ExpectSameAsCgal(RandomLabels(&random, size, label_count), label_count, &random,
                     "map " + std::to_string(map));
  }
}

TEST(BorderSimplificationTest, KeepsTheSamePointsAsCgalOnRoomsAndDiagonalWalls) {
  // Rooms along a corridor behind walls of 2 cells, a diagonal wall, a
  // staircase and pillars: long borders where the triangles grow long and
  // thin, beside parallel borders within a few pixels.
  std::mt19937 random(7);
  cv::Mat labels(160, 220, CV_32S, cv::Scalar(0));
  for (int k = 0; k < 5; ++k) {
    cv::rectangle(labels, cv::Rect(4 + 42 * k, 4, 40, 70), cv::Scalar(1 + k), cv::FILLED);
  }
  cv::rectangle(labels, cv::Rect(4, 76, 212, 20), cv::Scalar(6), cv::FILLED);
  for (int k = 0; k < 5; ++k) {
    cv::rectangle(labels, cv::Rect(20 + 42 * k, 74, 8, 2), cv::Scalar(6), cv::FILLED);
  }
  cv::fillConvexPoly(labels, std::vector<cv::Point>{{4, 98}, {216, 98}, {216, 156}, {60, 156}},
                     cv::Scalar(7), cv::LINE_8);
  cv::line(labels, {10, 100}, {200, 150}, cv::Scalar(0), 2, cv::LINE_8);
  for (int i = 0; i < 8; ++i) {
    cv::rectangle(labels, cv::Rect(110 + 6 * i, 110 + 4 * i, 3, 3), cv::Scalar(0), cv::FILLED);
  }
  ExpectSameAsCgal(labels, 7, &random, "rooms");
}

}  // namespace
}  // namespace areagraph

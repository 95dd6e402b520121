// ComputeAlphaComplex (one alpha, straight from the Delaunay triangulation)
// against CGAL's Alpha_shape_2, and the property furniture removal relies on.
#include <CGAL/Alpha_shape_2.h>
#include <CGAL/Alpha_shape_face_base_2.h>
#include <CGAL/Alpha_shape_vertex_base_2.h>
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <set>
#include <tuple>

#include "stages/geometry/alpha_shape.h"
#include "stages/geometry/cgal_types.h"
#include "stages/geometry/disjoint_sets.h"

namespace areagraph {
namespace {

using Kernel = cgal::Kernel;
using VertexBase =
    CGAL::Alpha_shape_vertex_base_2<Kernel,
                                    CGAL::Triangulation_vertex_base_with_info_2<int, Kernel>>;
using FaceBase = CGAL::Alpha_shape_face_base_2<Kernel>;
using Tds = CGAL::Triangulation_data_structure_2<VertexBase, FaceBase>;
using Delaunay = CGAL::Delaunay_triangulation_2<Kernel, Tds>;
using AlphaShape = CGAL::Alpha_shape_2<Delaunay>;

// Edges as point pairs: regular ones oriented, singular ones not.
using EdgeKey = std::tuple<double, double, double, double, bool>;

EdgeKey Key(Eigen::Vector2d a, Eigen::Vector2d b, bool singular) {
  if (singular && std::make_pair(a.x(), a.y()) > std::make_pair(b.x(), b.y())) std::swap(a, b);
  return {a.x(), a.y(), b.x(), b.y(), singular};
}

// The complex by CGAL's Alpha_shape_2 (GENERAL mode), for at least 3 points
// not all on a line: component labels and boundary edges.
void CgalComplex(const std::vector<Eigen::Vector2d>& points, double radius,
                 std::vector<int>* labels, std::multiset<EdgeKey>* edges) {
  const auto indexed = cgal::IndexedPoints(points);
  Delaunay dt(indexed.begin(), indexed.end());
  const AlphaShape shape(dt, radius * radius, AlphaShape::GENERAL);
  DisjointSets sets(points.size());
  for (auto e = shape.finite_edges_begin(); e != shape.finite_edges_end(); ++e) {
    const auto type = shape.classify(*e);
    if (type == AlphaShape::EXTERIOR) continue;
    auto face = e->first;
    int i = e->second;
    sets.Union(face->vertex(AlphaShape::cw(i))->info(), face->vertex(AlphaShape::ccw(i))->info());
    if (type == AlphaShape::INTERIOR) continue;
    if (type == AlphaShape::REGULAR && shape.classify(face) != AlphaShape::INTERIOR) {
      const auto neighbor = face->neighbor(i);
      i = neighbor->index(face);
      face = neighbor;
    }
    edges->insert(Key(points[face->vertex(AlphaShape::cw(i))->info()],
                      points[face->vertex(AlphaShape::ccw(i))->info()],
                      type == AlphaShape::SINGULAR));
  }
  *labels = sets.DenseLabels(nullptr);
}

void ExpectSameAsCgal(const std::vector<Eigen::Vector2d>& points, double radius) {
  std::vector<int> expected_labels;
  std::multiset<EdgeKey> expected_edges;
  CgalComplex(points, radius, &expected_labels, &expected_edges);
  const AlphaComplex complex = ComputeAlphaComplex(points, radius);
  EXPECT_EQ(complex.component_of_point, expected_labels) << "radius " << radius;
  std::multiset<EdgeKey> edges;
  for (const AlphaShapeEdge& edge : complex.boundary_edges) {
    edges.insert(Key(points[edge.a], points[edge.b], edge.singular));
  }
  EXPECT_EQ(edges, expected_edges) << "radius " << radius;
}

std::vector<Eigen::Vector2d> GridPoints(std::mt19937& random, int count, int span) {
  std::set<std::pair<int, int>> cells;
  while (int(cells.size()) < count) cells.insert({int(random() % span), int(random() % span)});
  std::vector<Eigen::Vector2d> points;
  for (const auto& [col, row] : cells) points.emplace_back(col + 0.5, row + 0.5);
  return points;
}

const double kRadii[] = {0.5, std::sqrt(0.5), 1, 1.5, 2, 2.5, 3, 5, 7.5, 10, 25};

TEST(AlphaComplex, MatchesAlphaShape2OnPixelGrids) {
  // Grid points are full of ties: co-circular quadruples, edges exactly as
  // long as the disk's diameter, right triangles with the radius exactly.
  std::mt19937 random(1);
  for (int trial = 0; trial < 40; ++trial) {
    const int span = 5 + int(random() % 40);
    const auto points = GridPoints(random, 3 + int(random() % (span * span / 3)), span);
    for (const double radius : kRadii) ExpectSameAsCgal(points, radius);
  }
}

TEST(AlphaComplex, MatchesAlphaShape2OnScatteredPoints) {
  std::mt19937 random(2);
  std::uniform_real_distribution<double> coordinate(0, 30);
  for (int trial = 0; trial < 40; ++trial) {
    std::vector<Eigen::Vector2d> points;
    const int count = 3 + int(random() % 300);
    for (int i = 0; i < count; ++i) points.emplace_back(coordinate(random), coordinate(random));
    for (const double radius : kRadii) ExpectSameAsCgal(points, radius);
  }
}

TEST(AlphaComplex, ComponentsAreThoseOfTheUnionOfDisks) {
  // Points join exactly when a chain of steps of at most the disk's diameter
  // links them; ag-clean leaves out points beyond that reach of any furniture.
  std::mt19937 random(4);
  for (int trial = 0; trial < 30; ++trial) {
    const int span = 10 + int(random() % 50);
    const auto points = GridPoints(random, 3 + int(random() % (span * 2)), span);
    for (const double radius : kRadii) {
      DisjointSets near(points.size());
      for (size_t i = 0; i < points.size(); ++i) {
        for (size_t j = i + 1; j < points.size(); ++j) {
          if ((points[i] - points[j]).squaredNorm() <= 4 * radius * radius) {
            near.Union(int(i), int(j));
          }
        }
      }
      EXPECT_EQ(ComputeAlphaComplex(points, radius).component_of_point, near.DenseLabels(nullptr))
          << "radius " << radius;
    }
  }
}

}  // namespace
}  // namespace areagraph

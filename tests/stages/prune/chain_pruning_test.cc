// Joining Voronoi chains and removing dead ends with their polygons.
#include "stages/prune/chain_pruning.h"

#include <gtest/gtest.h>

#include <utility>

#include "stages/prune/chain_graph.h"

namespace areagraph {
namespace {

// A straight chain from a to b in `steps` segments, with the walls `half`
// away on either side (left is -y for a chain along +x, pixel coordinates).
ChainEdge Chain(int source, int target, Eigen::Vector2d a, Eigen::Vector2d b, int steps,
                double half) {
  ChainEdge edge;
  edge.source = source;
  edge.target = target;
  const Eigen::Vector2d along = (b - a).normalized();
  const Eigen::Vector2d left(along.y(), -along.x());
  for (int i = 0; i <= steps; ++i) {
    edge.path.push_back(a + (b - a) * i / steps);
    edge.clearance_px.push_back(half);
  }
  for (int i = 0; i < steps; ++i) {
    const Eigen::Vector2d mid = a + (b - a) * (i + 0.5) / steps;
    edge.left_sites.push_back(mid + half * left);
    edge.right_sites.push_back(mid - half * left);
  }
  edge.min_clearance_px = half;
  return edge;
}

ChainGraph Star(double short_arm) {
  ChainGraph graph;
  graph.vertices = {
      {{0, 0}, 10}, {{100, 0}, 10}, {{-100, 0}, 10}, {{0, 100}, 10}, {{0, -short_arm}, 10}};
  graph.edges = {Chain(0, 1, {0, 0}, {100, 0}, 10, 10), Chain(0, 2, {0, 0}, {-100, 0}, 10, 10),
                 Chain(0, 3, {0, 0}, {0, 100}, 10, 10),
                 Chain(0, 4, {0, 0}, {0, -short_arm}, 3, 10)};
  return graph;
}

TEST(ChainGraphTest, DegreeTwoChainsJoinAndCyclesKeepOneJunction) {
  ChainGraph graph;
  graph.vertices = {{{0, 0}, 5}, {{10, 0}, 5}, {{20, 0}, 5}, {{30, 0}, 5}};
  graph.edges = {Chain(0, 1, {0, 0}, {10, 0}, 2, 5), Chain(2, 1, {20, 0}, {10, 0}, 2, 5),
                 Chain(2, 3, {20, 0}, {30, 0}, 2, 5)};
  graph.JoinDegreeTwoChains();
  ASSERT_EQ(graph.edges.size(), 1u);
  const ChainEdge& joined = graph.edges[0];
  EXPECT_EQ(joined.path.size(), 7u);
  EXPECT_EQ(joined.left_sites.size(), 6u);
  EXPECT_DOUBLE_EQ(joined.Length(), 30);
  // The reversed middle chain has its sides swapped back: left is -y.
  for (const Eigen::Vector2d& site : joined.left_sites) EXPECT_LT(site.y(), 0);

  ChainGraph cycle;
  cycle.vertices = {{{0, 0}, 5}, {{10, 0}, 5}, {{10, 10}, 5}};
  cycle.edges = {Chain(0, 1, {0, 0}, {10, 0}, 1, 5), Chain(1, 2, {10, 0}, {10, 10}, 1, 5),
                 Chain(2, 0, {10, 10}, {0, 0}, 1, 5)};
  cycle.JoinDegreeTwoChains();
  ASSERT_EQ(cycle.edges.size(), 1u);
  EXPECT_EQ(cycle.edges[0].source, cycle.edges[0].target);
  EXPECT_TRUE(cycle.vertices[cycle.edges[0].source].forced_junction);
}

TEST(ChainGraphTest, ReverseInPlaceEqualsReversed) {
  ChainEdge edge = Chain(3, 7, {0, 0}, {10, 5}, 4, 2);
  edge.clearance_px = {1, 2, 3, 4, 5};
  const ChainEdge expected = edge.Reversed();
  edge.Reverse();
  EXPECT_EQ(edge.source, 7);
  EXPECT_EQ(edge.target, 3);
  EXPECT_EQ(edge.path, expected.path);
  EXPECT_EQ(edge.clearance_px, expected.clearance_px);
  EXPECT_EQ(edge.left_sites, expected.left_sites);
  EXPECT_EQ(edge.right_sites, expected.right_sites);
  EXPECT_EQ(edge.path.front(), Eigen::Vector2d(10, 5));
  EXPECT_EQ(edge.clearance_px.front(), 5);
}

TEST(ChainPruningTest, ShortDeadEndGoesAndItsPolygonIsAbsorbed) {
  ChainGraph graph = Star(30);
  EXPECT_EQ(RemoveShortDeadEnds(&graph, 50), 1);
  EXPECT_TRUE(graph.edges[3].removed);
  // Clockwise on screen from straight up (-y) comes +x (edge 0), but that is
  // a dead end too, so the previous one, -x (edge 1), takes the polygon.
  ASSERT_EQ(graph.edges[1].absorbed.size(), 1u);
  EXPECT_EQ(graph.edges[0].absorbed.size() + graph.edges[2].absorbed.size(), 0u);
  graph.JoinDegreeTwoChains();
  ASSERT_EQ(graph.edges.size(), 3u);  // still a junction of three
  size_t absorbed = 0;
  for (const ChainEdge& edge : graph.edges) absorbed += edge.absorbed.size();
  EXPECT_EQ(absorbed, 1u);
}

TEST(ChainPruningTest, LongDeadEndStaysAndTheLastEdgeIsNeverRemoved) {
  ChainGraph graph = Star(80);
  EXPECT_EQ(RemoveShortDeadEnds(&graph, 50), 0);

  ChainGraph single;
  single.vertices = {{{0, 0}, 5}, {{10, 0}, 5}};
  single.edges = {Chain(0, 1, {0, 0}, {10, 0}, 2, 5)};
  EXPECT_EQ(RemoveShortDeadEnds(&single, 50), 0);
  EXPECT_FALSE(single.edges[0].removed);
}

TEST(ChainPruningTest, CornerSpurGoesWhateverItsLength) {
  ChainGraph graph = Star(80);
  // Arm 3 now separates one obstacle cell from the rest: a spur.
  for (Eigen::Vector2d& site : graph.edges[3].left_sites) site = {-20, -90};
  EXPECT_TRUE(IsCornerSpur(graph.edges[3]));
  EXPECT_FALSE(IsCornerSpur(graph.edges[0]));
  EXPECT_EQ(RemoveShortDeadEnds(&graph, 50), 1);
  EXPECT_TRUE(graph.edges[3].removed);
}

TEST(ChainPruningTest, CornerSpurSitesMayBeTouchingCells) {
  ChainGraph graph = Star(80);
  // Sites on the cell (-20.5, -90.5) and the cell diagonally beside it: still
  // one corner; a site two cells away makes a wall.
  PointList& sites = graph.edges[3].left_sites;
  for (size_t i = 0; i < sites.size(); ++i) {
    sites[i] = i % 2 ? Eigen::Vector2d(-19.5, -89.5) : Eigen::Vector2d(-20.5, -90.5);
  }
  EXPECT_TRUE(IsCornerSpur(graph.edges[3]));
  sites.back() = {-18.5, -90.5};
  EXPECT_FALSE(IsCornerSpur(graph.edges[3]));
}

// Junctions 0 (clearance 20) and 1 (15), 10 px apart, each with two more
// edges: 2 -> 0 and 3 -> 0, and `east` and `south` (to vertices 4 and 5) at 1.
ChainGraph CloseJunctions(ChainEdge east, ChainEdge south) {
  ChainGraph graph;
  graph.vertices = {{{0, 0}, 20},    {{10, 0}, 15},  {{-100, 0}, 10},
                    {{0, -100}, 10}, {{110, 0}, 10}, {{10, 100}, 10}};
  graph.edges = {Chain(0, 1, {0, 0}, {10, 0}, 2, 15), Chain(2, 0, {-100, 0}, {0, 0}, 5, 10),
                 Chain(3, 0, {0, -100}, {0, 0}, 5, 10), std::move(east), std::move(south)};
  return graph;
}

TEST(ChainPruningTest, JunctionsCloserThanTheirClearanceMerge) {
  ChainGraph graph =
      CloseJunctions(Chain(1, 4, {10, 0}, {110, 0}, 5, 10), Chain(1, 5, {10, 0}, {10, 100}, 5, 10));
  EXPECT_EQ(MergeCloseJunctions(&graph), 1);
  ASSERT_EQ(graph.edges.size(), 4u);
  for (const ChainEdge& edge : graph.edges) {
    EXPECT_TRUE(edge.source == 0 || edge.target == 0);
    EXPECT_TRUE(edge.path.front() == Eigen::Vector2d(0, 0) ||
                edge.path.back() == Eigen::Vector2d(0, 0));
    EXPECT_EQ(edge.left_sites.size() + 1, edge.path.size());
  }
  // The edges of the dropped junction run along the merged edge to it.
  EXPECT_DOUBLE_EQ(graph.edges[2].Length() + graph.edges[3].Length(), 220);
}

proto::Polygon Triangle(double x) {
  proto::Polygon polygon;
  for (const Eigen::Vector2d& p :
       {Eigen::Vector2d(x, 1), Eigen::Vector2d(x + 1, 1), Eigen::Vector2d(x, 2)}) {
    *polygon.mutable_outer()->add_points() = ToProtoPoint(p);
  }
  return polygon;
}

// The dropped junction's edges, one ending there and one starting there,
// both carrying absorbed polygons: each becomes the merged edge followed by
// itself, turned as it was, as copying Reversed() chains would make it.
TEST(ChainPruningTest, MergedJunctionsEdgesKeepTheirWayAndPolygons) {
  ChainGraph graph =
      CloseJunctions(Chain(4, 1, {110, 0}, {10, 0}, 4, 10), Chain(1, 5, {10, 0}, {10, 100}, 3, 10));
  graph.edges[3].absorbed = {Triangle(1), Triangle(2)};
  graph.edges[4].absorbed = {Triangle(3)};
  graph.edges[4].clearance_px.back() = 7;  // tells the ends apart
  ChainEdge bridge = graph.edges[0];
  auto extended = [&](const ChainEdge& other, bool at_target) {
    ChainEdge edge = bridge;
    edge.Append(at_target ? other.Reversed() : other);
    return at_target ? edge.Reversed() : edge;
  };
  const std::vector<ChainEdge> expected = {extended(graph.edges[3], true),
                                           extended(graph.edges[4], false)};
  ASSERT_EQ(MergeCloseJunctions(&graph), 1);
  ASSERT_EQ(graph.edges.size(), 4u);
  for (int k = 0; k < 2; ++k) {
    const ChainEdge& got = graph.edges[2 + k];
    const ChainEdge& want = expected[k];
    EXPECT_EQ(got.source, want.source);
    EXPECT_EQ(got.target, want.target);
    EXPECT_EQ(got.path, want.path);
    EXPECT_EQ(got.left_sites, want.left_sites);
    EXPECT_EQ(got.right_sites, want.right_sites);
    EXPECT_EQ(got.clearance_px, want.clearance_px);
    EXPECT_EQ(got.min_clearance_px, want.min_clearance_px);
    ASSERT_EQ(got.absorbed.size(), want.absorbed.size());
    for (size_t i = 0; i < got.absorbed.size(); ++i) {
      EXPECT_EQ(got.absorbed[i].SerializeAsString(), want.absorbed[i].SerializeAsString());
    }
  }
  EXPECT_EQ(graph.edges[2].target, 0);  // 4 -> 1 became 4 -> 0
  EXPECT_EQ(graph.edges[3].source, 0);  // 1 -> 5 became 0 -> 5
  EXPECT_EQ(graph.edges[2].absorbed.size(), 2u);
}

}  // namespace
}  // namespace areagraph

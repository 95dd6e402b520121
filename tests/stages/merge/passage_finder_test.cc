// FindPassages on hand-made cut graphs: a passage for each pair of areas at a
// vertex, as wide as the narrower edge end there, and one for nearby twins.
#include "stages/merge/passage_finder.h"

#include <gtest/gtest.h>

#include "stages/geometry/edge_polygon.h"
#include "tests/stages/merge/hand_made_cut_graph.h"

namespace areagraph::testing {
namespace {

// The sites left and right of one path segment.
struct SitePair {
  Eigen::Vector2d left, right;
};

// Sites `width` apart across the x axis at x: left above, right below.
SitePair Across(double x, double width) { return {{x, -width / 2}, {x, width / 2}}; }

// An edge whose path segments have these sites, first to last.
void AddEdgeWithSites(proto::CutGraph* graph, int source, int target,
                      const std::vector<SitePair>& sites) {
  proto::GraphEdge* edge = AddEdge(graph, source, target);
  for (const SitePair& pair : sites) {
    *edge->add_left_sites() = ToProtoPoint(pair.left);
    *edge->add_right_sites() = ToProtoPoint(pair.right);
  }
}

void ExpectPassage(const PassagePlan& passage, int area_a, int area_b, Eigen::Vector2d point,
                   const SitePair& sides) {
  EXPECT_EQ(passage.area_a, area_a);
  EXPECT_EQ(passage.area_b, area_b);
  EXPECT_EQ(passage.point, point);
  EXPECT_EQ(passage.side_a, sides.left);
  EXPECT_EQ(passage.side_b, sides.right);
  EXPECT_DOUBLE_EQ(passage.width_px, (sides.left - sides.right).norm());
}

TEST(PassageFinderTest, TwoAreasMeetInTheNarrowerOfTheirEdgeEnds) {
  // Each edge is narrowest at its far end, so only the right ends give 5.
  proto::CutGraph graph;
  const int left = AddVertex(&graph, VERTEX_JUNCTION, 0, 0, 0);
  const int door = AddVertex(&graph, VERTEX_PASSAGE, 0, 10, 0);
  const int right = AddVertex(&graph, VERTEX_JUNCTION, 0, 20, 0);
  AddEdgeWithSites(&graph, left, door, {Across(2.5, 12), Across(7.5, 5)});
  AddEdgeWithSites(&graph, door, right, {Across(12.5, 6), Across(17.5, 4)});
  std::vector<PassagePlan> passages = FindPassages(graph, {0, 1});
  ASSERT_EQ(passages.size(), 1u);
  ExpectPassage(passages[0], 0, 1, {10, 0}, Across(7.5, 5));
  // The lower area number comes first, whichever edge holds it.
  passages = FindPassages(graph, {1, 0});
  ASSERT_EQ(passages.size(), 1u);
  ExpectPassage(passages[0], 0, 1, {10, 0}, Across(7.5, 5));
}

TEST(PassageFinderTest, ThreeAreasAtAJunctionGiveAPassageForEachPair) {
  proto::CutGraph graph;
  const int junction = AddVertex(&graph, VERTEX_JUNCTION, 0, 0, 0);
  AddEdgeWithSites(&graph, junction, AddVertex(&graph, VERTEX_JUNCTION, 0, 9, 0),
                   {Across(1, 6), Across(5, 1)});
  AddEdgeWithSites(&graph, junction, AddVertex(&graph, VERTEX_JUNCTION, 0, 0, 9), {Across(0, 8)});
  AddEdgeWithSites(&graph, AddVertex(&graph, VERTEX_JUNCTION, 0, -9, 0), junction,
                   {Across(-5, 1), Across(-1, 10)});
  const std::vector<PassagePlan> passages = FindPassages(graph, {0, 1, 2});
  ASSERT_EQ(passages.size(), 3u);
  ExpectPassage(passages[0], 0, 1, {0, 0}, Across(1, 6));
  ExpectPassage(passages[1], 0, 2, {0, 0}, Across(1, 6));
  ExpectPassage(passages[2], 1, 2, {0, 0}, Across(0, 8));
}

TEST(PassageFinderTest, AnAreaOpensWithItsNarrowestEdgeEndAndNeverOntoItself) {
  // Area 0 reaches the junction over two edges (9 and 7 wide) that also
  // meet at their far end; area 1 over one 8 wide.
  proto::CutGraph graph;
  const int junction = AddVertex(&graph, VERTEX_JUNCTION, 0, 0, 0);
  const int far = AddVertex(&graph, VERTEX_JUNCTION, 0, 30, 0);
  AddEdgeWithSites(&graph, junction, far, {Across(1, 9)});
  AddEdgeWithSites(&graph, junction, far, {Across(2, 7)});
  AddEdgeWithSites(&graph, junction, AddVertex(&graph, VERTEX_JUNCTION, 0, 0, 30), {Across(3, 8)});
  const std::vector<PassagePlan> passages = FindPassages(graph, {0, 0, 1});
  ASSERT_EQ(passages.size(), 1u);
  ExpectPassage(passages[0], 0, 1, {0, 0}, Across(2, 7));
}

// Areas 0 and 1 meet at vertices at these x (on the x axis), with openings
// of these widths.
std::vector<PassagePlan> PassagesOfOnePair(const std::vector<std::pair<double, double>>& meetings) {
  proto::CutGraph graph;
  for (const auto& [x, width] : meetings) {
    const int vertex = AddVertex(&graph, VERTEX_PASSAGE, 0, x, 0);
    AddEdgeWithSites(&graph, AddVertex(&graph, VERTEX_JUNCTION, 0, x, -50), vertex,
                     {Across(x, width)});
    AddEdgeWithSites(&graph, vertex, AddVertex(&graph, VERTEX_JUNCTION, 0, x, 50),
                     {Across(x, width + 2)});
  }
  std::vector<int> area_of_edge;
  for (size_t k = 0; k < meetings.size(); ++k) area_of_edge.insert(area_of_edge.end(), {0, 1});
  return FindPassages(graph, area_of_edge);
}

TEST(PassageFinderTest, NearbyMeetingsOfOnePairAreOnePassageTheNarrowerKept) {
  // 4 px apart with openings of 10 and 8: one passage; 26 px further, another.
  std::vector<PassagePlan> passages = PassagesOfOnePair({{100, 10}, {104, 8}, {130, 8}});
  ASSERT_EQ(passages.size(), 2u);
  ExpectPassage(passages[0], 0, 1, {104, 0}, Across(104, 8));
  ExpectPassage(passages[1], 0, 1, {130, 0}, Across(130, 8));
  // The narrower one first: still kept.
  passages = PassagesOfOnePair({{100, 8}, {104, 10}});
  ASSERT_EQ(passages.size(), 1u);
  ExpectPassage(passages[0], 0, 1, {100, 0}, Across(100, 8));
  // 6 px apart is more than half of the wider opening: two passages.
  passages = PassagesOfOnePair({{100, 10}, {106, 8}});
  ASSERT_EQ(passages.size(), 2u);
  ExpectPassage(passages[0], 0, 1, {100, 0}, Across(100, 10));
  ExpectPassage(passages[1], 0, 1, {106, 0}, Across(106, 8));
}

TEST(PassageFinderTest, EdgesWithoutAreaOrSitesAreLeftOut) {
  proto::CutGraph graph;
  const int junction = AddVertex(&graph, VERTEX_JUNCTION, 0, 0, 0);
  AddEdgeWithSites(&graph, junction, AddVertex(&graph, VERTEX_JUNCTION, 0, 9, 0), {Across(1, 6)});
  AddEdgeWithSites(&graph, junction, AddVertex(&graph, VERTEX_JUNCTION, 0, 0, 9), {Across(2, 8)});
  AddEdgeWithSites(&graph, junction, AddVertex(&graph, VERTEX_JUNCTION, 0, -9, 0), {Across(3, 2)});
  AddEdgeWithSites(&graph, junction, AddVertex(&graph, VERTEX_JUNCTION, 0, 0, -9), {});
  const std::vector<PassagePlan> passages = FindPassages(graph, {0, 1, -1, 2});
  ASSERT_EQ(passages.size(), 1u);
  ExpectPassage(passages[0], 0, 1, {0, 0}, Across(1, 6));
}

TEST(PassageFinderTest, EmptyGraphHasNoPassages) {
  EXPECT_TRUE(FindPassages(proto::CutGraph(), {}).empty());
}

}  // namespace
}  // namespace areagraph::testing

// Areas that meet in open free space are joined by a passage on their border,
// also where no graph vertex put one; a gap narrower than a body stays shut.
#include "stages/merge/open_borders.h"

#include <gtest/gtest.h>

#include <set>
#include <string>
#include <utility>
#include <vector>

#include "stages/merge/area_graph_geometry.h"
#include "tests/stages/merge/hand_made_cut_graph.h"

namespace areagraph {
namespace {

using testing::AddStraightEdge;
using testing::AddVertex;

// A raster drawn row by row: '1' and '2' are the areas' cells, '.' none.
AreaRaster DrawnRaster(const std::vector<std::string>& rows) {
  AreaRaster raster;
  raster.labels = cv::Mat(static_cast<int>(rows.size()), static_cast<int>(rows[0].size()), CV_32S);
  for (int r = 0; r < raster.labels.rows; ++r) {
    for (int c = 0; c < raster.labels.cols; ++c) {
      raster.labels.at<int>(r, c) = rows[r][c] == '.' ? 0 : rows[r][c] - '0';
    }
  }
  raster.cell_count.assign(2, 0);
  CountAreaCells(&raster);
  return raster;
}

// Two rooms, each with its own Topology Graph edge across it; the edges
// share a vertex only with `shared_vertex` (then the vertex is a passage).
proto::CutGraph TwoEdges(bool shared_vertex) {
  proto::CutGraph graph;
  const int a = AddVertex(&graph, proto::VERTEX_DEAD_END, 2, 2, 5);
  const int m = AddVertex(&graph, proto::VERTEX_PASSAGE, 2, 6, 5);
  const int n = shared_vertex ? m : AddVertex(&graph, proto::VERTEX_DEAD_END, 2, 8, 5);
  const int b = AddVertex(&graph, proto::VERTEX_DEAD_END, 2, 10, 5);
  AddStraightEdge(&graph, a, m, 0, {2, 5}, {shared_vertex ? 6.0 : 4.0, 5}, 2, 4, 4);
  AddStraightEdge(&graph, n, b, 1, {shared_vertex ? 6.0 : 8.0, 5}, {10, 5}, 2, 4, 4);
  graph.set_min_clearance_m(0.15);  // prune.min_clearance_m's default
  return graph;
}

proto::AreaGraph Areas(const proto::CutGraph& graph, const AreaRaster& raster,
                       const proto::MergeOptions& options = {}) {
  AreaPlan plan;
  plan.areas.resize(2);
  plan.areas[0] = {proto::AREA_ROOM, 0, {0}};
  plan.areas[1] = {proto::AREA_ROOM, 1, {1}};
  plan.area_of_edge = {0, 1};
  proto::AreaGraph out;
  out.mutable_frame()->set_resolution_m(0.05);
  out.mutable_frame()->set_width_px(raster.labels.cols);
  out.mutable_frame()->set_height_px(raster.labels.rows);
  AddAreasAndPassages(graph, plan, raster, options, &out);
  return out;
}

// The outline vertices of an area, in metres.
std::set<std::pair<double, double>> Vertices(const proto::Area& area) {
  std::set<std::pair<double, double>> vertices;
  for (const proto::Point2& p : area.polygon_m().outer().points()) vertices.insert({p.x(), p.y()});
  return vertices;
}

// A 10 x 8 cell room (0.5 x 0.4 m) split down the middle between two areas,
// with nothing between them.
const std::vector<std::string> kOpenRoom{
    "............", ".1111122222.", ".1111122222.", ".1111122222.", ".1111122222.",
    ".1111122222.", ".1111122222.", ".1111122222.", ".1111122222.", "............"};

TEST(OpenBordersTest, AreasMeetingInOpenSpaceWithoutAVertexGetAPassageOnBothOutlines) {
  const proto::AreaGraph graph = Areas(TwoEdges(false), DrawnRaster(kOpenRoom));
  ASSERT_EQ(graph.areas_size(), 2);
  ASSERT_EQ(graph.passages_size(), 1);
  const proto::Passage& passage = graph.passages(0);
  EXPECT_EQ(std::make_pair(passage.area_a(), passage.area_b()), std::make_pair(0, 1));
  // The whole border between the rooms, from wall to wall: 8 cells.
  EXPECT_NEAR(passage.width_m(), 0.4, 1e-9);
  EXPECT_NEAR(passage.point_m().x(), 0.3, 1e-9);
  ASSERT_GE(passage.border_m_size(), 2);
  // Its ends are vertices of both areas' outlines (the planar partition).
  for (const proto::Point2* end : {&passage.segment_m().a(), &passage.segment_m().b()}) {
    const std::pair<double, double> at{end->x(), end->y()};
    EXPECT_EQ(Vertices(graph.areas(0)).count(at), 1u) << at.first << "," << at.second;
    EXPECT_EQ(Vertices(graph.areas(1)).count(at), 1u) << at.first << "," << at.second;
  }
  EXPECT_EQ(graph.areas(0).passage_ids_size(), 1);
  EXPECT_EQ(graph.areas(1).passage_ids_size(), 1);
}

// The two rooms kept apart by a wall column with a gap of `gap` cells.
std::vector<std::string> WallWithAGap(int gap) {
  std::vector<std::string> rows(12, std::string(13, '.'));
  for (int r = 1; r <= 10; ++r) {
    for (int c = 1; c <= 5; ++c) rows[r][c] = '1';
    for (int c = 7; c <= 11; ++c) rows[r][c] = '2';
    if (r >= 3 && r < 3 + gap) rows[r][6] = '1';
  }
  return rows;
}

TEST(OpenBordersTest, AGapNarrowerThanTheBodyStaysShut) {
  // The graph's min_clearance_m 0.15 m: 3 cells either side of the border.
  EXPECT_EQ(Areas(TwoEdges(false), DrawnRaster(WallWithAGap(5))).passages_size(), 0);
  const proto::AreaGraph wide = Areas(TwoEdges(false), DrawnRaster(WallWithAGap(6)));
  ASSERT_EQ(wide.passages_size(), 1);
  EXPECT_NEAR(wide.passages(0).width_m(), 0.3, 1e-9);
}

TEST(OpenBordersTest, ABorderWithAPassageAtAVertexGetsNoSecond) {
  const proto::AreaGraph graph = Areas(TwoEdges(true), DrawnRaster(kOpenRoom));
  ASSERT_EQ(graph.passages_size(), 1);
  // The passage found at the vertex, with the opening's width between the sites.
  EXPECT_NEAR(graph.passages(0).width_m(), 4 * 0.05, 1e-9);
}

TEST(OpenBordersTest, TheSkippedPassAddsNoPassage) {
  proto::MergeOptions options;
  options.add_skip_passes(proto::MergeOptions::OPEN_BORDER_PASSAGES);
  EXPECT_EQ(Areas(TwoEdges(false), DrawnRaster(kOpenRoom), options).passages_size(), 0);
  proto::CutGraph graph = TwoEdges(false);
  graph.set_min_clearance_m(0);
  EXPECT_EQ(Areas(graph, DrawnRaster(kOpenRoom)).passages_size(), 0);
}

TEST(OpenBordersTest, OnlyChainsBetweenTwoAreasAreTested) {
  const AreaRaster raster = DrawnRaster(WallWithAGap(6));
  const PlanarPartition partition = BuildPlanarPartition(raster.labels, 2);
  const std::vector<bool> passable = PassableChains(partition, raster.labels, 3);
  int between_areas = 0;
  for (size_t c = 0; c < partition.chains.size(); ++c) {
    const BorderChain& chain = partition.chains[c];
    const bool two_areas = chain.left != 0 && chain.right != 0;
    between_areas += two_areas;
    EXPECT_EQ(passable[c], two_areas) << "chain " << c;
  }
  EXPECT_EQ(between_areas, 1);
  EXPECT_EQ(PassableChains(partition, raster.labels, 0), std::vector<bool>(passable.size()));
}

}  // namespace
}  // namespace areagraph

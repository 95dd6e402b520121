// The viewer's layers, each from a small artifact made by hand.
#include "tools/export/viewer_layers.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <set>
#include <tuple>

#include "tests/tools/export/svg_path_parser.h"
#include "tests/tools/export/test_area_graph.h"
#include "tools/export/clearance_scale.h"
#include "tools/export/viewer_options.h"

namespace areagraph {
namespace {

using testing::PathSegments;

proto::MapFrame Frame(int width, int height) {
  proto::MapFrame frame;
  frame.set_resolution_m(0.05);
  frame.set_width_px(width);
  frame.set_height_px(height);
  return frame;
}

cv::Mat DecodePng(const std::string& bytes) {
  return cv::imdecode(
      cv::Mat(1, static_cast<int>(bytes.size()), CV_8UC1, const_cast<char*>(bytes.data())),
      cv::IMREAD_UNCHANGED);
}

TEST(GridMapPng, HasOneGreyPerCellState) {
  proto::GridMap grid;
  *grid.mutable_frame() = Frame(3, 2);
  grid.set_cells(std::string{proto::CELL_FREE, proto::CELL_OCCUPIED, proto::CELL_UNKNOWN,
                             proto::CELL_FREE, proto::CELL_FREE, proto::CELL_OCCUPIED});
  const cv::Mat image = DecodePng(GridMapPng(grid));
  ASSERT_EQ(image.type(), CV_8UC1);
  ASSERT_EQ(image.size(), cv::Size(3, 2));
  EXPECT_EQ(image.at<uint8_t>(0, 0), 255);
  EXPECT_LT(image.at<uint8_t>(0, 1), 64);
  EXPECT_EQ(image.at<uint8_t>(0, 2), 200);
  EXPECT_EQ(image.at<uint8_t>(1, 2), image.at<uint8_t>(0, 1));
}

TEST(GridMapPng, RefusesCellsThatDoNotMatchTheFrame) {
  proto::GridMap grid;
  *grid.mutable_frame() = Frame(3, 2);
  grid.set_cells("ab");
  EXPECT_THROW(GridMapPng(grid), std::exception);
}

TEST(CleanLayerOf, MarksOutliersFurnitureAndFreedCellsOnly) {
  proto::GridMap grid;
  *grid.mutable_frame() = Frame(4, 2);
  grid.set_cells(std::string{proto::CELL_OCCUPIED, proto::CELL_OCCUPIED, proto::CELL_UNKNOWN,
                             proto::CELL_UNKNOWN, proto::CELL_FREE, proto::CELL_FREE,
                             proto::CELL_FREE, proto::CELL_OCCUPIED});
  proto::CleanedMap cleaned;
  *cleaned.mutable_frame() = grid.frame();
  cleaned.set_cells(std::string{proto::CELL_FREE, proto::CELL_FREE, proto::CELL_FREE,
                                proto::CELL_UNKNOWN, proto::CELL_FREE, proto::CELL_FREE,
                                proto::CELL_FREE, proto::CELL_OCCUPIED});
  cleaned.add_removed_outlier_cells(0);
  cleaned.add_removed_furniture_cells(1);
  const viewer::CleanLayer layer = CleanLayerOf(cleaned, &grid);
  EXPECT_EQ(layer.outlier_cells(), 1);
  EXPECT_EQ(layer.furniture_cells(), 1);
  EXPECT_EQ(layer.freed_unknown_cells(), 1);
  const cv::Mat image = DecodePng(layer.changes_png());
  ASSERT_EQ(image.type(), CV_8UC1);
  EXPECT_EQ(image.at<uint8_t>(0, 0), viewer::CLEAN_OUTLIER);
  EXPECT_EQ(image.at<uint8_t>(0, 1), viewer::CLEAN_FURNITURE);
  EXPECT_EQ(image.at<uint8_t>(0, 2), viewer::CLEAN_FREED_UNKNOWN);
  for (int cell = 3; cell < 8; ++cell) {
    EXPECT_EQ(image.at<uint8_t>(cell / 4, cell % 4), viewer::CLEAN_UNCHANGED) << cell;
  }
}

// A 4x4 lattice of vertices joined right and down, clearances spread over
// the bands, plus one ray.
proto::VoronoiDiagram LatticeVoronoi() {
  proto::VoronoiDiagram voronoi;
  *voronoi.mutable_frame() = Frame(100, 100);
  for (int y = 0; y < 4; ++y) {
    for (int x = 0; x < 4; ++x) {
      proto::Point2* position = voronoi.add_vertices()->mutable_position();
      position->set_x(10 + 5 * x + 0.5);
      position->set_y(10 + 5 * y);
    }
  }
  int count = 0;
  auto add = [&](int a, int b) {
    proto::VoronoiEdge* edge = voronoi.add_edges();
    edge->set_source(a);
    edge->set_target(b);
    edge->set_clearance_px(1 + (count++ % 5) * 4);  // 1 px hugs; 5..17 px at 0.05 m
  };
  for (int y = 0; y < 4; ++y) {
    for (int x = 0; x < 4; ++x) {
      if (x < 3) add(4 * y + x, 4 * y + x + 1);
      if (y < 3) add(4 * y + x, 4 * y + x + 4);
    }
  }
  proto::VoronoiEdge* ray = voronoi.add_edges();
  ray->set_source(0);
  ray->set_clearance_px(30);
  return voronoi;
}

using Segment = std::tuple<double, double, double, double>;

Segment Undirected(double ax, double ay, double bx, double by) {
  return std::min(Segment(ax, ay, bx, by), Segment(bx, by, ax, ay));
}

TEST(VoronoiLayerOf, DrawsEveryFiniteEdgeOnceInItsClearanceBand) {
  const proto::VoronoiDiagram voronoi = LatticeVoronoi();
  const viewer::VoronoiLayer layer = VoronoiLayerOf(voronoi);
  std::multiset<Segment> drawn;
  std::set<std::string> colours;
  std::vector<viewer::PathBucket> buckets(layer.buckets().begin(), layer.buckets().end());
  ASSERT_TRUE(layer.has_hugging());
  EXPECT_EQ(layer.hugging().colour(), ClearanceBands()[0].colour);
  buckets.push_back(layer.hugging());
  for (const viewer::PathBucket& bucket : buckets) {
    colours.insert(bucket.colour());
    for (const auto& [a, b] : PathSegments(bucket.path())) {
      drawn.insert(Undirected(a.x, a.y, b.x, b.y));
      // Each segment sits in the band of its edge.
      for (const proto::VoronoiEdge& edge : voronoi.edges()) {
        if (edge.target() < 0) continue;
        const auto& s = voronoi.vertices(edge.source()).position();
        const auto& t = voronoi.vertices(edge.target()).position();
        if (Undirected(s.x(), s.y(), t.x(), t.y()) == Undirected(a.x, a.y, b.x, b.y)) {
          EXPECT_EQ(bucket.colour(),
                    ClearanceBands()[ClearanceBandOf(edge.clearance_px(), 0.05)].colour);
        }
      }
    }
  }
  std::multiset<Segment> expected;
  for (const proto::VoronoiEdge& edge : voronoi.edges()) {
    if (edge.target() < 0) continue;
    const auto& s = voronoi.vertices(edge.source()).position();
    const auto& t = voronoi.vertices(edge.target()).position();
    expected.insert(Undirected(s.x(), s.y(), t.x(), t.y()));
  }
  EXPECT_EQ(drawn, expected);
  EXPECT_EQ(colours.size(), 5u);
  EXPECT_EQ(layer.buckets_size(), 4);  // the hugging edges are apart
  EXPECT_EQ(layer.edges(), voronoi.edges_size());
}

TEST(VoronoiLayerOf, ChainsEdgesOfOneBandIntoLongPolylines) {
  proto::VoronoiDiagram voronoi = LatticeVoronoi();
  for (proto::VoronoiEdge& edge : *voronoi.mutable_edges()) edge.set_clearance_px(10);
  const viewer::VoronoiLayer layer = VoronoiLayerOf(voronoi);
  ASSERT_EQ(layer.buckets_size(), 1);
  // 24 edges; a lattice with 8 odd-degree vertices needs at least 4 chains.
  const auto subpaths = testing::ParseSvgPath(layer.buckets(0).path());
  EXPECT_LE(subpaths.size(), 8u);
  EXPECT_EQ(PathSegments(layer.buckets(0).path()).size(), 24u);
}

TEST(VoronoiLayerOf, EdgesAreClippedToTheMap) {
  proto::VoronoiDiagram voronoi;
  *voronoi.mutable_frame() = Frame(100, 50);
  for (const auto& [x, y] : {std::pair{50.0, 25.0}, {-50.0, 25.0}, {-50.0, -40.0}, {-10.0, 25.0}}) {
    proto::Point2* position = voronoi.add_vertices()->mutable_position();
    position->set_x(x);
    position->set_y(y);
  }
  for (const auto& [source, target] : {std::pair{0, 1}, {1, 2}, {2, 3}}) {
    proto::VoronoiEdge* edge = voronoi.add_edges();
    edge->set_source(source);
    edge->set_target(target);
    edge->set_clearance_px(10);
  }
  const viewer::VoronoiLayer layer = VoronoiLayerOf(voronoi);
  ASSERT_EQ(layer.buckets_size(), 1);
  // 0-1 crosses the left side and ends there; 1-2 lies outside; 2-3 passes
  // outside the corner.
  const auto segments = PathSegments(layer.buckets(0).path());
  ASSERT_EQ(segments.size(), 1u);
  const auto [a, b] = segments[0];
  EXPECT_DOUBLE_EQ(std::min(a.x, b.x), 0);
  EXPECT_DOUBLE_EQ(std::max(a.x, b.x), 50);
  EXPECT_DOUBLE_EQ(a.y, 25);
  EXPECT_DOUBLE_EQ(b.y, 25);
}

TEST(ClearanceBandOf, HuggingEdgesAndMetreLimits) {
  EXPECT_EQ(ClearanceBandOf(1.9, 0.05), 0);
  EXPECT_EQ(ClearanceBandOf(2.0, 0.05), 1);  // 0.10 m
  EXPECT_EQ(ClearanceBandOf(3.0, 0.05), 2);  // 0.15 m
  EXPECT_EQ(ClearanceBandOf(100, 0.05), static_cast<int>(ClearanceBands().size()) - 1);
  EXPECT_EQ(ClearanceBands().size(), std::size(kClearanceBandLimitsM) + 2);
}

TEST(RoomWidthOf, DoorsWiderThanTheWidestTakenDoNotCount) {
  proto::RoomWidthEstimate estimate;
  estimate.set_automatic(true);
  for (double width : {1.6, 1.0, 0.9, 0.9, 0.85, 0.8, 0.8, 0.8, 0.8, 0.8, 0.75}) {
    proto::DetectedWidth* door = estimate.add_doors();
    door->set_width_m(width);
  }
  estimate.set_widest_door_m(1.0);  // the 90th percentile of the 11 above
  estimate.set_narrowest_corridor_m(1.8);
  estimate.set_room_width_m(1.1);
  proto::CutOptions options;
  const viewer::RoomWidth width = RoomWidthOf(estimate, options);
  ASSERT_EQ(width.doors_size(), 11);
  EXPECT_FALSE(width.doors(0).counted());
  for (int i = 1; i < 11; ++i) EXPECT_TRUE(width.doors(i).counted()) << i;
  EXPECT_EQ(width.rule(), "estimated: widest door 1.00 m + 0.1 m");

  estimate.set_room_width_m(1.7);
  EXPECT_EQ(RoomWidthOf(estimate, options).rule(), "estimated: narrowest corridor 1.80 m - 0.1 m");
  estimate.set_automatic(false);
  EXPECT_EQ(RoomWidthOf(estimate, options).rule(), "fixed: cut.room_width_m");
}

TEST(AreaLayerOf, AreasAndPassagesInPixels) {
  const proto::AreaGraph graph = testing::TwoRoomAreaGraph();
  const viewer::AreaLayer layer = AreaLayerOf(graph);
  ASSERT_EQ(layer.areas_size(), 2);
  EXPECT_EQ(layer.areas(0).kind(), "room");
  EXPECT_EQ(layer.areas(1).kind(), "corridor");
  EXPECT_EQ(layer.areas(0).path(), "M2 2l10 0 0 10-10 0z");
  EXPECT_EQ(testing::ParseSvgPath(layer.areas(1).path()).size(), 2u);  // with its hole
  ASSERT_EQ(layer.passages_size(), 1);
  const viewer::Passage& passage = layer.passages(0);
  EXPECT_EQ(passage.area_a(), 0);
  EXPECT_EQ(passage.area_b(), 1);
  EXPECT_DOUBLE_EQ(passage.width_m(), 0.3);
  // Along x = 12 px from y 4 to 10 px, in either direction.
  EXPECT_DOUBLE_EQ(passage.a().x(), 12);
  EXPECT_DOUBLE_EQ(passage.b().x(), 12);
  EXPECT_DOUBLE_EQ(std::abs(passage.a().y() - passage.b().y()), 6);
}

TEST(AreaLayerOf, CarriesStableIdsOfAMatchedGraphOnly) {
  proto::AreaGraph graph = testing::TwoRoomAreaGraph();
  EXPECT_FALSE(AreaLayerOf(graph).areas(0).has_stable_id());
  EXPECT_FALSE(AreaLayerOf(graph).passages(0).has_stable_id());
  graph.mutable_version()->set_number(2);
  graph.mutable_areas(0)->set_stable_id(5);
  graph.mutable_areas(1)->set_stable_id(9);
  graph.mutable_passages(0)->set_stable_id(4);
  const viewer::AreaLayer layer = AreaLayerOf(graph);
  EXPECT_EQ(layer.areas(0).stable_id(), 5);
  EXPECT_EQ(layer.areas(1).stable_id(), 9);
  EXPECT_EQ(layer.areas(1).id(), 1);  // the index still links passages to areas
  EXPECT_EQ(layer.passages(0).stable_id(), 4);
}

TEST(StageOptionValues, FlagsTheOptionsThatDepartFromTheDefaults) {
  const auto values =
      StageOptionValues("cut", "room_width_m: 0.9\nroom_width_open_doors: true\ndoor_width_m: 0\n");
  ASSERT_FALSE(values.empty());
  int non_default = 0;
  for (const viewer::OptionValue& value : values) {
    if (value.is_default()) continue;
    ++non_default;
    EXPECT_TRUE(value.name() == "room_width_m" || value.name() == "room_width_open_doors")
        << value.name();
  }
  EXPECT_EQ(non_default, 2);
  EXPECT_EQ(values[0].name(), "room_width_m");
  EXPECT_EQ(values[0].value(), "0.9");
  EXPECT_EQ(values[0].default_value(), "0");
  EXPECT_TRUE(StageOptionValues("cut", "no_such_option: 1").empty());
  EXPECT_TRUE(StageOptionValues("no_such_stage", "").empty());
}

}  // namespace
}  // namespace areagraph

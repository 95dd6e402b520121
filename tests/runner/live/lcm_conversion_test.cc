// GridMap <-> grid_map_t and AreaGraph <-> area_graph_t, and the checks on
// what arrives over the network.
#include "runner/live/lcm_conversion.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "common/error.h"
#include "stages/common/map_frame.h"
#include "stages/match/area_graph_diff.h"
#include "tests/runner/live/lcm_test_maps.h"

namespace areagraph {
namespace {

using testing::MakeAreaGraph;
using testing::MakeGridMap;
using testing::ThrowsMessage;

TEST(GridMapConversion, FlipsRowsToRosOrderAndUsesRosValues) {
  const proto::GridMap grid = MakeGridMap();  // 3 x 2, top row F O U
  const areagraph_lcm::grid_map_t message = ToLcmGridMap("lab", 42, grid);
  EXPECT_EQ(message.name, "lab");
  EXPECT_EQ(message.utime, 42);
  EXPECT_EQ(message.width, 3);
  EXPECT_EQ(message.height, 2);
  EXPECT_EQ(message.num_cells, 6);
  // ROS row 0 is the bottom row: U O F, then the top row F O U.
  const std::vector<int8_t> expected = {-1, 100, 0, 0, 100, -1};
  EXPECT_EQ(message.cells, expected);
  EXPECT_DOUBLE_EQ(message.resolution_m, 0.05);
  EXPECT_DOUBLE_EQ(message.origin_x_m, -1.5);
  EXPECT_DOUBLE_EQ(message.origin_yaw_rad, 0.25);
}

TEST(GridMapConversion, RoundTripGivesTheSameGrid) {
  const proto::GridMap grid = MakeGridMap();
  const proto::GridMap back = GridMapFromLcm(ToLcmGridMap("lab", 1, grid));
  EXPECT_EQ(back.cells(), grid.cells());
  EXPECT_EQ(back.frame().SerializeAsString(), grid.frame().SerializeAsString());
  EXPECT_EQ(back.format_version(), 1u);
}

TEST(GridMapConversion, ClassifiesProbabilitiesLikeMapSaver) {
  areagraph_lcm::grid_map_t message = ToLcmGridMap("lab", 1, MakeGridMap());
  message.cells = {25, 26, 64, 65, 1, 99};
  const proto::GridMap grid = GridMapFromLcm(message);
  // The top row (ROS row 1) comes first.
  const std::string expected = {proto::CELL_OCCUPIED, proto::CELL_FREE,    proto::CELL_OCCUPIED,
                                proto::CELL_FREE,     proto::CELL_UNKNOWN, proto::CELL_UNKNOWN};
  EXPECT_EQ(grid.cells(), expected);
}

TEST(GridMapConversion, RejectsInvalidGrids) {
  const areagraph_lcm::grid_map_t good = ToLcmGridMap("lab", 1, MakeGridMap());
  auto with = [&good](auto change) {
    areagraph_lcm::grid_map_t message = good;
    change(message);
    return message;
  };
  using M = areagraph_lcm::grid_map_t;
  EXPECT_TRUE(ThrowsMessage(
      [&] { GridMapFromLcm(with([](M& m) { m.resolution_m = 0; })); },
      "grid_map_t 'lab': resolution_m must be a resolution in [0.0001, 1000] metres per pixel, "
      "got 0"));
  EXPECT_TRUE(ThrowsMessage(
      [&] { GridMapFromLcm(with([](M& m) { m.resolution_m = std::nan(""); })); },
      "resolution_m must be a resolution in [0.0001, 1000] metres per pixel, got nan"));
  EXPECT_TRUE(ThrowsMessage(
      [&] {
        GridMapFromLcm(with([](M& m) { m.origin_x_m = std::numeric_limits<double>::infinity(); }));
      },
      "origin x and y must be finite metres within +-1e+08, got inf"));
  EXPECT_TRUE(ThrowsMessage([&] { GridMapFromLcm(with([](M& m) { m.origin_y_m = 1.7e308; })); },
                            "origin x and y must be finite metres within +-1e+08"));
  EXPECT_TRUE(ThrowsMessage([&] { GridMapFromLcm(with([](M& m) { m.origin_yaw_rad = 1e9; })); },
                            "origin yaw must be finite radians within +-2 pi"));
  EXPECT_TRUE(ThrowsMessage([&] { GridMapFromLcm(with([](M& m) { m.resolution_m = 1e-300; })); },
                            "resolution_m must be a resolution in [0.0001, 1000]"));
  EXPECT_TRUE(ThrowsMessage([&] { GridMapFromLcm(with([](M& m) { m.width = 0; })); },
                            "size 0x2 is not positive"));
  EXPECT_TRUE(ThrowsMessage([&] { GridMapFromLcm(with([](M& m) { m.width = 4; })); },
                            "has 6 cells (num_cells 6) but width * height is 8"));
  EXPECT_TRUE(ThrowsMessage([&] { GridMapFromLcm(with([](M& m) { m.cells.pop_back(); })); },
                            "has 5 cells (num_cells 6) but width * height is 6"));
  EXPECT_TRUE(ThrowsMessage([&] { GridMapFromLcm(with([](M& m) { m.cells[4] = 101; })); },
                            "cell (1, 1) has value 101; valid are -1 (unknown) and 0..100"));
  EXPECT_TRUE(ThrowsMessage([&] { GridMapFromLcm(with([](M& m) { m.cells[0] = -2; })); },
                            "cell (0, 0) has value -2"));
  EXPECT_TRUE(ThrowsMessage([&] { GridMapFromLcm(with([](M& m) { m.name = "a b"; })); },
                            "grid_map_t: map name 'a b' holds a blank"));
  EXPECT_TRUE(ThrowsMessage([&] { GridMapFromLcm(with([](M& m) { m.name.clear(); })); },
                            "map name is empty"));
  EXPECT_TRUE(ThrowsMessage([&] { GridMapFromLcm(with([](M& m) { m.name = "../x"; })); },
                            "map name '../x' may not hold a '..' part"));
  EXPECT_EQ(GridMapFromLcm(with([](M& m) { m.name = "floor1/wing_a"; })).cells().size(),
            GridMapFromLcm(good).cells().size());
  EXPECT_TRUE(ThrowsMessage([&] { GridMapFromLcm(good, /*max_cells=*/5); },
                            "3x2 cells exceed the limit of 5 (import.max_pixels)"));
  // A huge claimed size is refused before anything is allocated.
  EXPECT_TRUE(
      ThrowsMessage([&] { GridMapFromLcm(with([](M& m) { m.width = m.height = 2000000000; })); },
                    "exceed the limit of 100000000"));
}

TEST(AreaGraphConversion, CarriesAreasAndPassagesInMetres) {
  const proto::AreaGraph graph = MakeAreaGraph();
  const areagraph_lcm::area_graph_t message = ToLcmAreaGraph("lab", "abc123", graph);
  EXPECT_EQ(message.map_name, "lab");
  EXPECT_EQ(message.artifact_key, "abc123");
  EXPECT_EQ(message.width_px, 100);
  ASSERT_EQ(message.num_areas, 2);
  ASSERT_EQ(message.areas.size(), 2u);
  EXPECT_EQ(message.areas[0].kind, areagraph_lcm::area_t::ROOM);
  EXPECT_EQ(message.areas[1].kind, areagraph_lcm::area_t::CORRIDOR);
  EXPECT_EQ(message.areas[0].outer.num_points, 4);
  EXPECT_DOUBLE_EQ(message.areas[0].outer.x[1], 2.0);
  EXPECT_EQ(message.areas[0].num_holes, 1);
  EXPECT_EQ(message.areas[1].num_holes, 0);
  EXPECT_EQ(message.areas[1].passage_ids, std::vector<int32_t>{7});
  ASSERT_EQ(message.num_passages, 1);
  EXPECT_EQ(message.passages[0].area_a, 0);
  EXPECT_EQ(message.passages[0].area_b, 1);
  EXPECT_DOUBLE_EQ(message.passages[0].ax, 2.0);
  EXPECT_DOUBLE_EQ(message.passages[0].width_m, 0.9);
  ASSERT_EQ(message.passages[0].num_border_points, 3);
  EXPECT_DOUBLE_EQ(message.passages[0].border_y[1], 0.45);
}

TEST(AreaGraphConversion, RoundTripKeepsEverythingTheTypeCarries) {
  const proto::AreaGraph graph = MakeAreaGraph();
  const proto::AreaGraph back = AreaGraphFromLcm(ToLcmAreaGraph("lab", "abc123", graph));
  ASSERT_EQ(back.areas_size(), graph.areas_size());
  for (int i = 0; i < graph.areas_size(); ++i) {
    const proto::Area& want = graph.areas(i);
    const proto::Area& got = back.areas(i);
    // Ids become indices; the message's ids are kept as stable ids.
    EXPECT_EQ(got.id(), i);
    EXPECT_EQ(got.stable_id(), want.id());
    EXPECT_EQ(got.kind(), want.kind());
    EXPECT_EQ(got.polygon_m().SerializeAsString(), want.polygon_m().SerializeAsString());
    EXPECT_EQ(got.area_m2(), want.area_m2());
    EXPECT_EQ(got.centroid_m().SerializeAsString(), want.centroid_m().SerializeAsString());
    EXPECT_EQ(got.passage_ids_size(), want.passage_ids_size());
    // Pixel polygons are recomputed through the frame.
    ASSERT_EQ(got.polygon_px().outer().points_size(), want.polygon_m().outer().points_size());
    const MapTransform transform(graph.frame());
    const Eigen::Vector2d pixel = transform.WorldToPixel(
        {want.polygon_m().outer().points(2).x(), want.polygon_m().outer().points(2).y()});
    EXPECT_NEAR(got.polygon_px().outer().points(2).x(), pixel.x(), 1e-9);
    EXPECT_NEAR(got.polygon_px().outer().points(2).y(), pixel.y(), 1e-9);
  }
  EXPECT_EQ(back.areas(0).polygon_px().holes_size(), 1);
  ASSERT_EQ(back.passages_size(), 1);
  proto::Passage passage = back.passages(0);
  EXPECT_EQ(passage.stable_id(), 7);
  EXPECT_EQ(back.areas(0).passage_ids(0), 0);  // the index of passage 7
  passage.clear_stable_id();
  passage.set_id(7);
  EXPECT_EQ(passage.SerializeAsString(), graph.passages(0).SerializeAsString());
  EXPECT_EQ(back.frame().SerializeAsString(), graph.frame().SerializeAsString());
  EXPECT_FALSE(back.has_version());  // a graph without stable ids goes out as version 0
}

TEST(AreaGraphConversion, AVersionGoesOutWithItsStableIdsAndPlace) {
  proto::AreaGraph first, second;
  testing::MakeTwoVersions(first, second);
  const areagraph_lcm::area_graph_t message = ToLcmAreaGraph("lab", "second-key", second);
  EXPECT_EQ(message.version, 2);
  EXPECT_EQ(message.predecessor_key, "first-key");
  EXPECT_EQ(message.utime, 0);  // the publisher sets these
  EXPECT_EQ(message.sequence, 0);
  ASSERT_EQ(message.num_areas, 3);
  std::vector<int32_t> area_ids;
  for (const areagraph_lcm::area_t& area : message.areas) area_ids.push_back(area.id);
  EXPECT_EQ(area_ids, (std::vector<int32_t>{0, 1, 2}));
  ASSERT_EQ(message.num_passages, 2);
  // Passage 7 of the merge artifact is stable passage 0; 8 is the new one.
  EXPECT_EQ(message.passages[0].id, 0);
  EXPECT_EQ(message.passages[1].id, 1);
  EXPECT_EQ(message.passages[1].area_a, 1);
  EXPECT_EQ(message.passages[1].area_b, 2);
  EXPECT_EQ(message.areas[1].passage_ids, (std::vector<int32_t>{0, 1}));

  // What a listener makes of it: ids as indices, the rest as sent.
  const proto::AreaGraph back = AreaGraphFromLcm(message);
  EXPECT_EQ(back.version().number(), 2);
  EXPECT_EQ(back.version().predecessor_key(), "first-key");
  EXPECT_EQ(back.version().next_area_id(), 3);
  for (int i = 0; i < 3; ++i) {
    EXPECT_EQ(back.areas(i).id(), i);
    EXPECT_EQ(back.areas(i).stable_id(), second.areas(i).stable_id());
  }
  EXPECT_EQ(back.passages(1).stable_id(), 1);
  EXPECT_EQ(back.passages(1).area_b(), 2);
}

TEST(AreaGraphConversion, ADiffCarriesWhatChangedAsItIsNow) {
  proto::AreaGraph first, second;
  testing::MakeTwoVersions(first, second);
  const proto::AreaGraphDiff diff = DiffAreaGraphs(first, second);
  const areagraph_lcm::area_graph_diff_t message =
      ToLcmAreaGraphDiff("lab", "second-key", diff, second);
  EXPECT_EQ(message.map_name, "lab");
  EXPECT_EQ(message.artifact_key, "second-key");
  EXPECT_EQ(message.version, 2);
  EXPECT_EQ(message.predecessor_version, 1);
  EXPECT_EQ(message.predecessor_key, "first-key");
  ASSERT_EQ(message.num_added_areas, 1);
  EXPECT_EQ(message.added_areas[0].id, 2);
  EXPECT_EQ(message.added_areas[0].kind, areagraph_lcm::area_t::DEAD_END);
  EXPECT_EQ(message.num_removed_areas, 0);
  ASSERT_EQ(message.num_changed_areas, 1);  // the corridor; the room is the same
  EXPECT_EQ(message.changed_areas[0].area.id, 1);
  EXPECT_EQ(message.changed_areas[0].changes,
            areagraph_lcm::area_change_t::GROWN | areagraph_lcm::area_change_t::PASSAGES);
  EXPECT_DOUBLE_EQ(message.changed_areas[0].area.outer.y[2], 1.3);
  EXPECT_EQ(message.unchanged_areas, 1);
  ASSERT_EQ(message.num_added_passages, 1);
  EXPECT_EQ(message.added_passages[0].id, 1);
  EXPECT_EQ(message.num_changed_passages, 0);  // the door moved 0.1 m
  EXPECT_EQ(message.unchanged_passages, 1);
}

TEST(AreaGraphConversion, RejectsInconsistentGraphs) {
  const areagraph_lcm::area_graph_t good = ToLcmAreaGraph("lab", "k", MakeAreaGraph());
  auto with = [&good](auto change) {
    areagraph_lcm::area_graph_t message = good;
    change(message);
    return message;
  };
  using G = areagraph_lcm::area_graph_t;
  EXPECT_TRUE(ThrowsMessage([&] { AreaGraphFromLcm(with([](G& g) { g.areas[1].id = 0; })); },
                            "area_graph_t for map 'lab': two areas have id 0"));
  EXPECT_TRUE(ThrowsMessage([&] { AreaGraphFromLcm(with([](G& g) { g.areas[0].kind = 7; })); },
                            "area 0 has unknown kind 7"));
  EXPECT_TRUE(ThrowsMessage([&] { AreaGraphFromLcm(with([](G& g) { g.passages[0].area_b = 9; })); },
                            "passage 7 joins an area that is not in the graph"));
  EXPECT_TRUE(ThrowsMessage(
      [&] { AreaGraphFromLcm(with([](G& g) { g.areas[0].outer.x[0] = std::nan(""); })); },
      "area 0 outline x is not finite"));
  EXPECT_TRUE(ThrowsMessage(
      [&] {
        AreaGraphFromLcm(with([](G& g) {
          g.areas[1].outer.num_points = 2;
          g.areas[1].outer.x.resize(2);
          g.areas[1].outer.y.resize(2);
        }));
      },
      "area 1 outline has fewer than 3 points"));
  EXPECT_TRUE(ThrowsMessage(
      [&] { AreaGraphFromLcm(with([](G& g) { g.passages[0].border_x[1] = INFINITY; })); },
      "passage 7 border x is not finite"));
  EXPECT_TRUE(ThrowsMessage([&] { AreaGraphFromLcm(with([](G& g) { g.resolution_m = -1; })); },
                            "resolution_m must be positive and finite"));
  EXPECT_TRUE(
      ThrowsMessage([&] { AreaGraphFromLcm(with([](G& g) { g.areas[1].passage_ids = {8}; })); },
                    "area 1 lists passage 8, which is not in the graph"));
}

}  // namespace
}  // namespace areagraph

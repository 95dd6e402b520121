// RoomWidthM and ChooseRoomWidth: a fixed W, the paper's strategy from door
// and corridor widths, W estimated from the Topology Graph and its fallback,
// and the options and widths they refuse.
#include "stages/cut/room_width.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>

#include "common/error.h"
#include "stages/cut/width_estimate.h"
#include "tests/support/area_test_support.h"
#include "tools/example_maps/floor_plan.h"

namespace areagraph::testing {
namespace {

// A frame of width_px x height_px cells of resolution_m.
proto::MapFrame Frame(int width_px, int height_px, double resolution_m = 0.05) {
  proto::MapFrame frame;
  frame.set_resolution_m(resolution_m);
  frame.set_width_px(width_px);
  frame.set_height_px(height_px);
  return frame;
}

// A map big enough for every W used here: 20 x 10 m.
const proto::MapFrame kBigMap = Frame(400, 200);
// clean.robot_width_m's default, which the CleanedMap carries to cut.
const double kRobotWidthM = proto::CleanOptions().robot_width_m();

proto::CutOptions Fixed(double room_width_m) {
  proto::CutOptions options;
  options.set_room_width_m(room_width_m);
  return options;
}

proto::CutOptions Strategy(double door_m, double corridor_m) {
  proto::CutOptions options;
  options.set_door_width_m(door_m);
  options.set_corridor_width_m(corridor_m);
  return options;
}

// A Topology Graph of one straight edge along y = 20 from x = 0 to x =
// length_px, with a path point every pixel and walls `clearance_px(x)` away
// on either side at path point x.
proto::TopologyGraph OneEdge(int length_px, const std::function<double(int)>& clearance_px) {
  proto::TopologyGraph graph;
  for (int k = 0; k < 2; ++k) {
    proto::GraphVertex* vertex = graph.add_vertices();
    vertex->set_id(k);
    vertex->set_kind(proto::VERTEX_DEAD_END);
  }
  proto::GraphEdge* edge = graph.add_edges();
  edge->set_source(0);
  edge->set_target(1);
  for (int x = 0; x <= length_px; ++x) {
    proto::Point2* point = edge->add_path();
    point->set_x(x);
    point->set_y(20);
    edge->add_clearance_px(clearance_px(x));
    if (x == length_px) break;
    proto::Point2* left = edge->add_left_sites();
    left->set_x(x + 0.5);
    left->set_y(20 - clearance_px(x));
    proto::Point2* right = edge->add_right_sites();
    right->set_x(x + 0.5);
    right->set_y(20 + clearance_px(x));
  }
  edge->set_length_px(length_px);
  return graph;
}

// 6 m of corridor, (2 * 20 - 1) px = 1.95 m free.
const proto::TopologyGraph kCorridor = OneEdge(120, [](int) { return 20.0; });
// The same with a 0.85 m door ((2 * 9 - 1) px) in the middle, 2.7 m of
// corridor on either side.
const proto::TopologyGraph kCorridorWithADoor =
    OneEdge(120, [](int x) { return x >= 55 && x <= 65 ? 9.0 : 20.0; });

// The OptionsError that `run` throws, or "" when it does not throw one.
std::string OptionsErrorOf(const std::function<void()>& run) {
  try {
    run();
  } catch (const OptionsError& error) {
    return error.what();
  }
  return "";
}

TEST(RoomWidthTest, FixedWidthIsRoomWidthM) {
  EXPECT_DOUBLE_EQ(RoomWidthM(Fixed(1.1), kBigMap), 1.1);
  // The default (0, to be estimated) gives the paper's W.
  EXPECT_DOUBLE_EQ(RoomWidthM(proto::CutOptions(), kBigMap), kPaperRoomWidthM);
  // Door and corridor of 0 make no difference.
  proto::CutOptions options = Fixed(0.9);
  options.set_door_width_m(0);
  options.set_corridor_width_m(0);
  EXPECT_DOUBLE_EQ(RoomWidthM(options, kBigMap), 0.9);
}

TEST(RoomWidthTest, StrategyIsDoorPlusOrCorridorMinusATenth) {
  // Door narrower than the corridor: door + 0.1 m, whatever room_width_m says.
  proto::CutOptions options = Strategy(0.9, 1.6);
  options.set_room_width_m(3);
  EXPECT_NEAR(RoomWidthM(options, kBigMap), 1.0, 1e-12);
  // Door as wide as or wider than the corridor: corridor - 0.1 m.
  EXPECT_NEAR(RoomWidthM(Strategy(1.0, 1.0), kBigMap), 0.9, 1e-12);
  EXPECT_NEAR(RoomWidthM(Strategy(1.5, 1.2), kBigMap), 1.1, 1e-12);
}

TEST(RoomWidthTest, WiderThanTheMapIsRefused) {
  const proto::MapFrame map = Frame(4, 2, 0.25);       // 1 x 0.5 m
  EXPECT_DOUBLE_EQ(RoomWidthM(Fixed(1.0), map), 1.0);  // as wide as its longer side: fits
  const std::string fixed = OptionsErrorOf([&] { RoomWidthM(Fixed(1.01), map); });
  EXPECT_EQ(fixed, "the room width W = 1.01 m is wider than the map (1 x 0.5 m)");
  const std::string strategy = OptionsErrorOf([&] { RoomWidthM(Strategy(0.95, 2), map); });
  EXPECT_NE(strategy.find("W = 1.05 m is wider than the map"), std::string::npos) << strategy;
  // Rotated, the same map fits the same W.
  EXPECT_DOUBLE_EQ(RoomWidthM(Fixed(1.0), Frame(2, 4, 0.25)), 1.0);
}

TEST(RoomWidthTest, BadOptionsAreRefused) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  const std::vector<std::pair<proto::CutOptions, std::string>> cases = {
      {Fixed(-1), "cut.room_width_m must be zero or more"},
      {Fixed(nan), "cut.room_width_m must be zero or more"},
      {Fixed(inf), "cut.room_width_m must be zero or more"},
      {Strategy(0.9, 0), "set both or neither"},
      {Strategy(0, 1.6), "set both or neither"},
      {Strategy(-0.9, 1.6), "cut.door_width_m must be a positive number"},
      {Strategy(nan, 1.6), "cut.door_width_m must be a positive number"},
      {Strategy(0.9, inf), "cut.corridor_width_m must be a positive number"},
      {Strategy(3, 0.05), "gives no room width"},
  };
  for (const auto& [options, message] : cases) {
    const std::string fixed = OptionsErrorOf([&] { RoomWidthM(options, kBigMap); });
    EXPECT_NE(fixed.find(message), std::string::npos) << "'" << fixed << "' for " << message;
    // Also before any estimate.
    const std::string chosen = OptionsErrorOf(
        [&] { ChooseRoomWidth(options, kBigMap, kCorridorWithADoor, kRobotWidthM); });
    EXPECT_NE(chosen.find(message), std::string::npos) << "'" << chosen << "' for " << message;
  }
  // A corridor just over 0.1 m still gives a width, and a narrow door with it.
  EXPECT_NEAR(RoomWidthM(Strategy(3, 0.15), kBigMap), 0.05, 1e-12);
  EXPECT_NEAR(RoomWidthM(Strategy(0.05, 0.1), kBigMap), 0.15, 1e-12);
}

TEST(ChooseRoomWidthTest, FixedOrStrategyIsNotAutomatic) {
  // The strategy wins over an estimated W (room_width_m 0).
  const proto::CutOptions strategy = Strategy(0.9, 1.6);
  for (const proto::CutOptions& options : {Fixed(1.1), strategy}) {
    const proto::RoomWidthEstimate chosen =
        ChooseRoomWidth(options, kBigMap, kCorridorWithADoor, kRobotWidthM);
    EXPECT_FALSE(chosen.automatic());
    EXPECT_DOUBLE_EQ(chosen.room_width_m(), RoomWidthM(options, kBigMap));
    EXPECT_EQ(chosen.doors_size() + chosen.corridors_size(), 0);
    EXPECT_EQ(chosen.widest_door_m(), 0);
  }
}

TEST(ChooseRoomWidthTest, AutomaticFollowsTheDoorsAndCorridorsFound) {
  proto::CutOptions options;  // auto, W above the doors, fallback 1.25 m
  const proto::RoomWidthEstimate door =
      ChooseRoomWidth(options, kBigMap, kCorridorWithADoor, kRobotWidthM);
  EXPECT_TRUE(door.automatic());
  ASSERT_EQ(door.doors_size(), 1);
  EXPECT_NEAR(door.doors(0).position().x(), 60, 1e-9);
  EXPECT_NEAR(door.widest_door_m(), 0.85, 1e-9);
  EXPECT_NEAR(door.narrowest_corridor_m(), 1.95, 1e-9);
  EXPECT_NEAR(door.room_width_m(), 0.85 + kPaperWidthMarginM, 1e-9);
  // Without doors: corridor - 0.1 m.
  const proto::RoomWidthEstimate corridor =
      ChooseRoomWidth(options, kBigMap, kCorridor, kRobotWidthM);
  EXPECT_TRUE(corridor.automatic());
  EXPECT_EQ(corridor.doors_size(), 0);
  EXPECT_NEAR(corridor.narrowest_corridor_m(), 1.95, 1e-9);
  EXPECT_NEAR(corridor.room_width_m(), 1.85, 1e-9);
}

TEST(ChooseRoomWidthTest, WStaysAboveTheRobotsWidth) {
  // The 0.85 m door gives W = 0.95 m for a body 0.5 m wide. A body 1 m wide
  // passes no such door: W is held at its width and the paper's margin.
  const proto::CutOptions options;
  EXPECT_NEAR(ChooseRoomWidth(options, kBigMap, kCorridorWithADoor, 0.5).room_width_m(), 0.95,
              1e-9);
  EXPECT_NEAR(ChooseRoomWidth(options, kBigMap, kCorridorWithADoor, 1.0).room_width_m(),
              1.0 + kPaperWidthMarginM, 1e-9);
}

TEST(ChooseRoomWidthTest, DoorWiderThanTheCorridorFollowsRoomWidthAboveDoors) {
  // Two 2 m stretches 3.95 m wide with a 1.45 m door between them, then
  // 10.45 m of corridor 1.15 m wide.
  const proto::TopologyGraph graph = OneEdge(300, [](int x) {
    if (x > 40 && x < 50) return 15.0;
    return x <= 90 ? 40.0 : 12.0;
  });
  proto::CutOptions options;
  const proto::RoomWidthEstimate above = ChooseRoomWidth(options, kBigMap, graph, kRobotWidthM);
  ASSERT_EQ(above.doors_size(), 1);
  EXPECT_NEAR(above.doors(0).position().x(), 45, 1e-9);
  EXPECT_NEAR(above.widest_door_m(), 1.45, 1e-9);
  EXPECT_NEAR(above.narrowest_corridor_m(), 1.15, 1e-9);
  EXPECT_NEAR(above.room_width_m(), 1.45 + kPaperWidthMarginM, 1e-9);
  options.add_skip_passes(proto::CutOptions::WIDTH_ABOVE_DOORS);  // the paper's rule
  EXPECT_NEAR(ChooseRoomWidth(options, kBigMap, graph, kRobotWidthM).room_width_m(), 1.05, 1e-9);
}

TEST(ChooseRoomWidthTest, AutomaticFallsBackToThePapersW) {
  const proto::CutOptions options;
  // 1 m of constant width along one edge: too short for a corridor, no door.
  const proto::TopologyGraph short_edge = OneEdge(20, [](int) { return 10.0; });
  for (const proto::TopologyGraph& graph : {proto::TopologyGraph(), short_edge}) {
    const proto::RoomWidthEstimate chosen = ChooseRoomWidth(options, kBigMap, graph, kRobotWidthM);
    EXPECT_TRUE(chosen.automatic());
    EXPECT_EQ(chosen.doors_size(), 0);
    EXPECT_EQ(chosen.narrowest_corridor_m(), 0);
    EXPECT_DOUBLE_EQ(chosen.room_width_m(), kPaperRoomWidthM);
  }
}

TEST(ChooseRoomWidthTest, EstimateWiderThanTheMapIsRefused) {
  // 1.5 m square: the fallback of 1.25 m fits, the 1.85 m estimated does not.
  const std::string error = OptionsErrorOf(
      [] { ChooseRoomWidth(proto::CutOptions(), Frame(30, 30), kCorridor, kRobotWidthM); });
  EXPECT_NE(error.find("W = 1.85 m is wider than the map"), std::string::npos) << error;
}

TEST(ChooseRoomWidthTest, DrawnMapGetsItsDoorWidthPlusATenth) {
  // Three rooms above a corridor 2 m between wall centres, 0.9 m doors.
  floorplan::FloorPlan plan(12, 7.5);
  for (int i = 0; i < 3; ++i) floorplan::DrawRoom(plan, {0.5 + i * 3.5, 0.5, 3.5, 4.5});
  floorplan::DrawRoom(plan, {0.5, 5.0, 11, 2.0});
  for (int i = 0; i < 3; ++i) {
    floorplan::DrawDoor(plan, 0.5 + (i + 0.5) * 3.5, 5.0, 0.9,
                        floorplan::WallDirection::kHorizontal);
  }
  const proto::CleanedMap map = CleanedMapFromImage(plan.image());
  const AreaStages stages = RunAreaStages(map);
  const proto::RoomWidthEstimate chosen =
      ChooseRoomWidth(proto::CutOptions(), map.frame(), stages.topology, kRobotWidthM);
  EXPECT_TRUE(chosen.automatic());
  EXPECT_EQ(chosen.doors_size(), 3);
  EXPECT_NEAR(chosen.room_width_m(), 0.9 + kPaperWidthMarginM, 0.1);
  EXPECT_DOUBLE_EQ(chosen.room_width_m(), chosen.widest_door_m() + kPaperWidthMarginM);
  // What ag-cut stored is this choice.
  EXPECT_DOUBLE_EQ(stages.cut.room_width().room_width_m(), chosen.room_width_m());
  // The paper's strategy ignores the map.
  EXPECT_NEAR(ChooseRoomWidth(Strategy(0.9, 1.6), map.frame(), stages.topology, kRobotWidthM)
                  .room_width_m(),
              1.0, 1e-12);
}

}  // namespace
}  // namespace areagraph::testing

namespace areagraph::testing {
namespace {

// An automatic estimate with doors of 1.8, 1.8, 0.9, 0.9 and 0.9 m (widest
// first, W = 1.9 m) and a 1.2 m corridor, and the narrowing openings of
// those doors, each closed or not.
struct DoorsAround {
  proto::RoomWidthEstimate estimate;
  std::vector<Opening> openings;
  DoorsAround(const std::vector<bool>& closed) {
    estimate.set_automatic(true);
    estimate.set_room_width_m(1.9);
    estimate.set_narrowest_corridor_m(1.2);
    const double widths[] = {1.8, 1.8, 0.9, 0.9, 0.9};
    for (int k = 0; k < 5; ++k) {
      estimate.add_doors()->set_width_m(widths[k]);
      Opening& door = openings.emplace_back();
      door.position = Eigen::Vector2d(100.0 * k, 0);
      door.width_m = widths[k];
      door.closed = closed[k];
    }
  }
};

TEST(KeepWidthAboveOpenDoorsTest, ClosedDoubleDoorsLeaveWAboveTheSingleDoors) {
  proto::CutOptions options;
  options.set_room_width_open_doors(true);
  const ClosedLines none(PointList(), 0.05);
  DoorsAround doors({true, true, false, false, false});
  KeepWidthAboveOpenDoors(doors.openings, none, options, kRobotWidthM, &doors.estimate);
  EXPECT_DOUBLE_EQ(doors.estimate.widest_open_door_m(), 0.9);
  // 0.9 + 0.1 is below the corridor: W stays above the corridor (1.3 m).
  EXPECT_NEAR(doors.estimate.room_width_m(), 1.3, 1e-9);
  // One double door open: W stays above it, as before.
  DoorsAround one_open({false, true, false, false, false});
  KeepWidthAboveOpenDoors(one_open.openings, none, options, kRobotWidthM, &one_open.estimate);
  EXPECT_NEAR(one_open.estimate.room_width_m(), 1.9, 1e-9);
}

TEST(KeepWidthAboveOpenDoorsTest, ADoorOnAClosedLineIsClosed) {
  proto::CutOptions options;
  const PointList line = {{100, -1}, {100, 0}, {100, 1}};  // across the second door
  DoorsAround doors({true, false, false, false, false});
  KeepWidthAboveOpenDoors(doors.openings, ClosedLines(line, 0.05), options, kRobotWidthM,
                          &doors.estimate);
  EXPECT_DOUBLE_EQ(doors.estimate.widest_open_door_m(), 0.9);
  DoorsAround open({true, false, false, false, false});
  KeepWidthAboveOpenDoors(open.openings, ClosedLines(PointList(), 0.05), options, kRobotWidthM,
                          &open.estimate);
  EXPECT_DOUBLE_EQ(open.estimate.widest_open_door_m(), 1.8);
}

}  // namespace
}  // namespace areagraph::testing

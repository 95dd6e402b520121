// The area stages on drawn floor plans: the number of areas and passages,
// where the passages are, and the invariants every Area Graph must meet.
#include <gtest/gtest.h>

#include <set>

#include "tests/support/area_test_support.h"
#include "tools/example_maps/floor_plan.h"

namespace areagraph::testing {
namespace {

using floorplan::DrawDoor;
using floorplan::DrawRoom;
using floorplan::FloorPlan;
using floorplan::RectM;
using floorplan::WallDirection;

// A passage's point in plan metres (y down from the top), for maps whose
// origin is (0, 0).
Eigen::Vector2d PlanPoint(const proto::Passage& passage, const proto::CleanedMap& map) {
  const double height_m = map.frame().height_px() * map.frame().resolution_m();
  return {passage.point_m().x(), height_m - passage.point_m().y()};
}

// Three 10/3 m wide rooms above a corridor with about 1.6 m free between its
// walls, each joined to it by a 0.9 m door; the doors' x go to `door_xs`.
FloorPlan CorridorWithThreeRooms(std::vector<double>* door_xs = nullptr) {
  FloorPlan plan(11, 6.5);
  const double room_width = 10.0 / 3;
  for (int i = 0; i < 3; ++i) DrawRoom(plan, {0.5 + i * room_width, 0.5, room_width, 3.5});
  DrawRoom(plan, {0.5, 4.0, 10, 1.75});
  for (int i = 0; i < 3; ++i) {
    const double door_x = 0.5 + (i + 0.5) * room_width;
    if (door_xs != nullptr) door_xs->push_back(door_x);
    DrawDoor(plan, door_x, 4.0, 0.9, WallDirection::kHorizontal);
  }
  return plan;
}

TEST(AreaStagesTest, OneRoomIsOneArea) {
  FloorPlan plan(6, 5);
  DrawRoom(plan, {0.5, 0.5, 5, 4});
  const proto::CleanedMap map = CleanedMapFromImage(plan.image());
  const AreaStages stages = RunAreaStages(map);
  ExpectAreaGraphInvariants(stages, map);
  ASSERT_EQ(stages.areas.areas_size(), 1);
  EXPECT_EQ(stages.areas.passages_size(), 0);
  EXPECT_EQ(stages.areas.areas(0).kind(), proto::AREA_ROOM);
  // The free inside is about 4.85 x 3.85 m.
  EXPECT_NEAR(stages.areas.areas(0).area_m2(), 4.85 * 3.85, 0.5);
}

TEST(AreaStagesTest, TwoRoomsJoinedByADoorAreTwoAreasWithOnePassage) {
  const FloorPlan plan = TwoRoomsWithADoor();
  const proto::CleanedMap map = CleanedMapFromImage(plan.image());
  const AreaStages stages = RunAreaStages(map);
  ExpectAreaGraphInvariants(stages, map);
  ASSERT_EQ(stages.areas.areas_size(), 2);
  ASSERT_EQ(stages.areas.passages_size(), 1);
  const proto::Passage& door = stages.areas.passages(0);
  EXPECT_LT((PlanPoint(door, map) - Eigen::Vector2d(4.5, 2.5)).norm(), 0.3);
  EXPECT_NEAR(door.width_m(), 0.9, 0.15);
  const int left = AreaAt(stages.areas, 2.5, 2.5), right = AreaAt(stages.areas, 6.5, 2.5);
  EXPECT_NE(left, -1);
  EXPECT_NE(right, -1);
  EXPECT_NE(left, right);
  EXPECT_EQ(std::set<int>({door.area_a(), door.area_b()}), std::set<int>({left, right}));
}

TEST(AreaStagesTest, CorridorWithThreeRoomsIsFourAreasWithThreePassages) {
  std::vector<double> doors;
  const FloorPlan plan = CorridorWithThreeRooms(&doors);
  const proto::CleanedMap map = CleanedMapFromImage(plan.image());
  const AreaStages stages = RunAreaStages(map);
  ExpectAreaGraphInvariants(stages, map);
  ASSERT_EQ(stages.areas.areas_size(), 4);
  ASSERT_EQ(stages.areas.passages_size(), 3);
  const int corridor = AreaAt(stages.areas, 5.5, 4.9);
  ASSERT_NE(corridor, -1);
  for (const proto::Passage& passage : stages.areas.passages()) {
    EXPECT_TRUE(passage.area_a() == corridor || passage.area_b() == corridor);
    EXPECT_NEAR(passage.width_m(), 0.9, 0.15);
    const Eigen::Vector2d at = PlanPoint(passage, map);
    double nearest = 1e9;
    for (double x : doors) nearest = std::min(nearest, (at - Eigen::Vector2d(x, 4.0)).norm());
    EXPECT_LT(nearest, 0.3) << "passage at " << at.transpose();
  }
}

TEST(AreaStagesTest, MazeHasOneAreaPerTopologyGraphEdge) {
  const proto::CleanedMap map = CleanedMapFromImage(FiveByFiveMaze().image());
  const AreaStages stages = RunAreaStages(map, PaperMazeOptions());
  ExpectAreaGraphInvariants(stages, map);
  EXPECT_EQ(stages.cut.room_shapes_size(), 0);
  EXPECT_EQ(stages.cut.edges_size(), stages.topology.edges_size());
  // This maze has two junctions, four dead ends and one corridor between them.
  EXPECT_GE(stages.topology.edges_size(), 5);
  ASSERT_EQ(stages.areas.areas_size(), stages.topology.edges_size());
  int corridors = 0;
  for (const proto::Area& area : stages.areas.areas()) {
    ASSERT_EQ(area.topology_edge_ids_size(), 1);
    const proto::GraphEdge& edge = stages.cut.edges(area.topology_edge_ids(0));
    const proto::VertexKind source = stages.cut.vertices(edge.source()).kind();
    const proto::VertexKind target = stages.cut.vertices(edge.target()).kind();
    // Dead end to junction, or junction to junction.
    EXPECT_TRUE(source == proto::VERTEX_JUNCTION || target == proto::VERTEX_JUNCTION);
    // The piece between the junctions is a corridor; the pieces out to a
    // dead end are not (a long one is a dead end, a short one is as squat
    // as a small room: SetAreaKinds goes by shape).
    if (source == target) {
      EXPECT_EQ(area.kind(), proto::AREA_CORRIDOR);
    } else {
      EXPECT_NE(area.kind(), proto::AREA_CORRIDOR);
    }
    corridors += area.kind() == proto::AREA_CORRIDOR;
  }
  EXPECT_GE(corridors, 1);
}

TEST(AreaStagesTest, LShapedCorridorNarrowerThanTheRoomWidthIsOneArea) {
  // 1.0 m free between the walls, W = 1.25 m.
  const proto::CleanedMap map = CleanedMapFromImage(LCorridor().image());
  // A fixed W (auto, the default, takes corridor - 0.1 m here: one room).
  proto::PipelineOptions options;
  options.mutable_cut()->set_room_width_m(1.25);  // a fixed W (0, the default, estimates it)
  const AreaStages stages = RunAreaStages(map, options);
  ExpectAreaGraphInvariants(stages, map);
  EXPECT_EQ(stages.cut.room_shapes_size(), 0);
  ASSERT_EQ(stages.areas.areas_size(), 1);
  EXPECT_EQ(stages.areas.passages_size(), 0);
}

TEST(AreaStagesTest, NarrowerRoomWidthStrategyMakesTheCorridorARoom) {
  // Door 0.9 < corridor 1.6: W = 1.0 m. The corridor still holds the disk,
  // so the result matches the fixed W of 1.25 m: four room shapes. Its
  // length makes the corridor's area a corridor again (SetAreaKinds).
  const FloorPlan plan = CorridorWithThreeRooms();
  const proto::CleanedMap map = CleanedMapFromImage(plan.image());
  proto::PipelineOptions options;
  options.mutable_cut()->set_door_width_m(0.9);
  options.mutable_cut()->set_corridor_width_m(1.6);
  const AreaStages stages = RunAreaStages(map, options);
  ExpectAreaGraphInvariants(stages, map);
  EXPECT_EQ(stages.areas.areas_size(), 4);
  EXPECT_EQ(stages.areas.passages_size(), 3);
  int rooms = 0;
  for (const proto::Area& area : stages.areas.areas()) rooms += area.kind() == proto::AREA_ROOM;
  EXPECT_EQ(rooms, 3);
}

// With KEEP_SMALL_CLOSED_ROOMS the rooms stay: each is one area behind
// a door the cut closed, narrower than the room, with its walls seen.
TEST(AreaStagesTest, MinimumAreaFoldsSmallAreasIntoNeighbours) {
  const FloorPlan plan = CorridorWithThreeRooms();
  const proto::CleanedMap map = CleanedMapFromImage(plan.image());
  for (const bool keep_closed : {false, true}) {
    SCOPED_TRACE(keep_closed ? "keep_small_closed_rooms" : "fold every small area");
    proto::PipelineOptions options;
    // The rooms hold about 10.5 m2 each, the corridor about 15.5 m2.
    options.mutable_merge()->set_min_area_m2(12);
    if (!keep_closed) {
      options.mutable_merge()->add_skip_passes(proto::MergeOptions::KEEP_SMALL_CLOSED_ROOMS);
    }
    const AreaStages stages = RunAreaStages(map, options);
    ExpectAreaGraphInvariants(stages, map);
    EXPECT_EQ(stages.areas.areas_size(), keep_closed ? 4 : 1);
    EXPECT_EQ(stages.areas.passages_size(), keep_closed ? 3 : 0);
  }
}

// A door narrower than twice the clearance keeps the Topology Graph out of
// the small room (only the biggest connected group is kept), so no area's
// edge reaches it: the big room's area must not grow through the door.
// A room behind a door narrower than twice the clearance is no part of its
// own (its free cells touch the rest through the door), so the paper's rule
// holds: the Topology Graph does not reach it, and with the growth limit it
// stays unlabelled.
TEST(AreaStagesTest, RoomBehindATooNarrowDoorStaysUnlabelled) {
  FloorPlan plan(9.5, 5);
  DrawRoom(plan, {0.5, 0.5, 5, 4});
  DrawRoom(plan, {5.5, 0.5, 3.5, 4});
  DrawDoor(plan, 5.5, 2.5, 0.35, WallDirection::kVertical);
  const proto::CleanedMap map = CleanedMapFromImage(plan.image());
  // The paper's clearance (the default, 0.15 m, lets 0.3 m gaps through).
  proto::PipelineOptions options;
  options.mutable_prune()->set_min_clearance_m(0.25);
  const AreaStages stages = RunAreaStages(map, options);
  // The small room is 40 % of the free space.
  ExpectAreaGraphInvariants(stages, map, /*min_coverage=*/0.55);
  EXPECT_EQ(stages.topology.parts(), 1);
  EXPECT_EQ(stages.topology.dropped_parts(), 0);
  EXPECT_EQ(stages.areas.components(), 1);
  ASSERT_EQ(stages.areas.areas_size(), 1);
  EXPECT_NE(AreaAt(stages.areas, 3, 2.5), -1);
  EXPECT_EQ(AreaAt(stages.areas, 7.25, 2.5), -1);
  EXPECT_EQ(AreaAt(stages.areas, 6, 1), -1);
  // The big room is covered up to the door.
  EXPECT_NEAR(stages.areas.areas(0).area_m2(), 4.85 * 3.85, 0.5);

  // Growing everywhere (the pass skipped, as in the paper) floods the small
  // room too.
  options.mutable_merge()->add_skip_passes(proto::MergeOptions::GROWTH_STOPS_AT_NARROW_GAPS);
  const AreaStages flooded = RunAreaStages(map, options);
  ASSERT_EQ(flooded.areas.areas_size(), 1);
  EXPECT_NE(AreaAt(flooded.areas, 7.25, 2.5), -1);
}

// Two buildings on one map, with unknown space between them (the issue's
// 2 x 2 tiles of lab_a kept one tile): both get their areas, as two
// components, and a closet too small to be an area is dropped and counted.
TEST(AreaStagesTest, EveryBuildingOfAMapGetsItsAreas) {
  const proto::CleanedMap one = CleanedMapFromImage(CorridorWithThreeRooms().image());
  const AreaStages single = RunAreaStages(one);
  ASSERT_EQ(single.areas.components(), 1);

  // More than two alpha disks (3 m radius) apart: two boundary regions.
  FloorPlan plan(36, 6.5);
  const double room_width = 10.0 / 3;
  for (const double left : {0.5, 24.5}) {
    for (int i = 0; i < 3; ++i) DrawRoom(plan, {left + i * room_width, 0.5, room_width, 3.5});
    DrawRoom(plan, {left, 4.0, 10, 1.75});
    for (int i = 0; i < 3; ++i) {
      DrawDoor(plan, left + (i + 0.5) * room_width, 4.0, 0.9, WallDirection::kHorizontal);
    }
  }
  DrawRoom(plan, {17.0, 2.0, 1.2, 1.2});  // a closet of 1 m2 between them
  const proto::CleanedMap map = CleanedMapFromImage(plan.image());
  const AreaStages stages = RunAreaStages(map);
  ExpectAreaGraphInvariants(stages, map);
  EXPECT_EQ(stages.topology.parts(), 2);
  EXPECT_EQ(stages.topology.part_boundaries_size(), 2);
  EXPECT_EQ(stages.areas.components(), 2);
  EXPECT_EQ(stages.areas.areas_size(), 2 * single.areas.areas_size());
  EXPECT_EQ(stages.areas.passages_size(), 2 * single.areas.passages_size());
  EXPECT_NE(AreaAt(stages.areas, 2, 2), -1);
  EXPECT_NE(AreaAt(stages.areas, 26, 2), -1);
  EXPECT_EQ(AreaAt(stages.areas, 17.6, 2.6), -1);
  EXPECT_EQ(stages.areas.dropped_parts(), 1);
  // The closet's free cells: 1.2 m less a wall thickness (0.15 m) each way.
  EXPECT_NEAR(stages.areas.dropped_area_m2(), 1.05 * 1.05, 0.15);

  // The paper's behaviour keeps the bigger building's graph only.
  proto::PipelineOptions paper;
  paper.mutable_prune()->set_min_component_m2(1e8);
  const AreaStages one_building = RunAreaStages(map, paper);
  EXPECT_EQ(one_building.areas.components(), 1);
  EXPECT_EQ(one_building.areas.areas_size(), single.areas.areas_size());
  EXPECT_EQ(one_building.areas.dropped_parts(), 2);
}

// A wing reached only through unknown space: one corridor runs from the
// main building to the wing, but a 3 m stretch of it (walls and all) was
// never scanned. Both sides lie in one boundary region (the gap is narrower
// than the alpha disk), yet their free space is not connected: the wing is a
// part of its own and keeps its rooms and its piece of the corridor. Before,
// only the longest graph stayed and the wing's rooms had no area.
TEST(AreaStagesTest, WingBehindUnknownSpaceGetsItsAreas) {
  FloorPlan plan(26, 6.5);
  const double room_width = 10.0 / 3;
  for (const double left : {0.5, 15.5}) {
    for (int i = 0; i < 3; ++i) DrawRoom(plan, {left + i * room_width, 0.5, room_width, 3.5});
  }
  DrawRoom(plan, {0.5, 4.0, 25, 1.75});
  for (const double left : {0.5, 15.5}) {
    for (int i = 0; i < 3; ++i) {
      DrawDoor(plan, left + (i + 0.5) * room_width, 4.0, 0.9, WallDirection::kHorizontal);
    }
  }
  const int gap_left = plan.ToPixels(11.5), gap_top = plan.ToPixels(3.6);
  plan.image()(
          cv::Rect(gap_left, gap_top, plan.ToPixels(14.5) - gap_left, plan.ToPixels(6.2) - gap_top))
      .setTo(floorplan::kUnknownGrey);
  const proto::CleanedMap map = CleanedMapFromImage(plan.image());
  const AreaStages stages = RunAreaStages(map);
  ExpectAreaGraphInvariants(stages, map);
  EXPECT_EQ(stages.topology.parts(), 2);
  EXPECT_EQ(stages.topology.part_boundaries_size(), 1);  // one alpha-shape region
  EXPECT_EQ(stages.topology.dropped_parts(), 0);
  EXPECT_EQ(stages.areas.components(), 2);
  // Every room of both sides and both pieces of the corridor have an area.
  std::set<int> areas;
  for (const double left : {0.5, 15.5}) {
    for (int i = 0; i < 3; ++i)
      areas.insert(AreaAt(stages.areas, left + (i + 0.5) * room_width, 2));
  }
  areas.insert(AreaAt(stages.areas, 5, 4.9));
  areas.insert(AreaAt(stages.areas, 20, 4.9));
  EXPECT_EQ(areas.count(-1), 0u);
  EXPECT_EQ(areas.size(), 8u);

  // The paper's rule (only the biggest graph) leaves the wing without areas.
  proto::PipelineOptions paper;
  paper.mutable_prune()->set_min_component_m2(1e8);
  const AreaStages biggest_only = RunAreaStages(map, paper);
  EXPECT_EQ(biggest_only.areas.components(), 1);
  EXPECT_EQ(biggest_only.areas.dropped_parts(), 1);
  int wing_areas = 0;
  for (int i = 0; i < 3; ++i) {
    wing_areas += AreaAt(biggest_only.areas, 15.5 + (i + 0.5) * room_width, 2) != -1 ? 1 : 0;
  }
  EXPECT_EQ(wing_areas, 0);
}

// A door as wide as the limit still lets the areas grow: the room behind
// it is reached by the graph and gets its own area.
TEST(AreaStagesTest, NormalDoorsAreNotGrowthLimits) {
  FloorPlan plan(9.5, 5);
  DrawRoom(plan, {0.5, 0.5, 5, 4});
  DrawRoom(plan, {5.5, 0.5, 3.5, 4});
  DrawDoor(plan, 5.5, 2.5, 0.8, WallDirection::kVertical);
  const proto::CleanedMap map = CleanedMapFromImage(plan.image());
  const AreaStages stages = RunAreaStages(map);
  ExpectAreaGraphInvariants(stages, map);
  EXPECT_NE(AreaAt(stages.areas, 3, 2.5), -1);
  EXPECT_NE(AreaAt(stages.areas, 7.25, 2.5), -1);
}

// A 1 m wide alcove off a room is a dead-end area of its own in the paper;
// at about 2.3 m2 it is below merge.min_area_m2 (4 m2 by default) and folds
// into the room.
TEST(AreaStagesTest, TinyAreasFoldIntoTheirRoomByDefault) {
  FloorPlan plan(9, 5);
  DrawRoom(plan, {0.5, 0.5, 5, 4});
  DrawRoom(plan, {5.5, 1.6, 2.5, 1.0});
  DrawDoor(plan, 5.5, 2.1, 0.8, WallDirection::kVertical);
  const proto::CleanedMap map = CleanedMapFromImage(plan.image());

  proto::PipelineOptions paper;
  paper.mutable_merge()->set_min_area_m2(0);
  // The 0.8 m door is about as wide as the niche: a bay, folded by default.
  paper.mutable_merge()->add_skip_passes(proto::MergeOptions::FOLD_OPEN_BAYS);
  const AreaStages kept = RunAreaStages(map, paper);
  ExpectAreaGraphInvariants(kept, map);
  EXPECT_EQ(kept.areas.areas_size(), 2);
  const int room = AreaAt(kept.areas, 3, 2.5), niche = AreaAt(kept.areas, 7, 2.1);
  EXPECT_NE(room, -1);
  EXPECT_NE(niche, -1);
  EXPECT_NE(room, niche);

  const AreaStages folded = RunAreaStages(map);
  ExpectAreaGraphInvariants(folded, map);
  ASSERT_EQ(folded.areas.areas_size(), 1);
  EXPECT_EQ(folded.areas.passages_size(), 0);
  EXPECT_EQ(AreaAt(folded.areas, 7, 2.1), 0);
  EXPECT_EQ(AreaAt(folded.areas, 3, 2.5), 0);
}

// Cells that ag-clean freed (outliers, furniture) are no area's by default;
// merge.cover_removed_obstacles = true (the paper) covers them too.
TEST(AreaStagesTest, RemovedObstacleCellsStayOutsideTheAreas) {
  FloorPlan plan(6, 5);
  DrawRoom(plan, {0.5, 0.5, 5, 4});
  proto::CleanedMap map = CleanedMapFromImage(plan.image());
  const int width = map.frame().width_px();
  // Three cells in the room that cleaning freed.
  const std::vector<int> removed = {40 * width + 40, 40 * width + 41, 60 * width + 70};
  for (int index : removed) map.add_removed_outlier_cells(index);
  map.add_removed_furniture_cells(50 * width + 30);

  const AreaStages stages = RunAreaStages(map);
  ExpectAreaGraphInvariants(stages, map);
  ASSERT_EQ(stages.areas.areas_size(), 1);
  for (int index : {removed[0], removed[1], removed[2], 50 * width + 30}) {
    EXPECT_EQ(stages.raster.labels.at<int>(index / width, index % width), 0);
  }
  EXPECT_EQ(stages.raster.labels.at<int>(40, 42), 1);

  proto::PipelineOptions options;
  options.mutable_merge()->set_cover_removed_obstacles(true);
  const AreaStages covered = RunAreaStages(map, options);
  ASSERT_EQ(covered.areas.areas_size(), 1);
  for (int index : removed) {
    EXPECT_EQ(covered.raster.labels.at<int>(index / width, index % width), 1);
  }
}

}  // namespace
}  // namespace areagraph::testing

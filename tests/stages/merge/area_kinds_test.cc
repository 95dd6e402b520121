// The areas' kinds (SetAreaKinds) through the whole pipeline on drawn
// floors: a corridor loop around a block of rooms, an L corridor, a hall
// with rooms around it and a dead end behind a door; and on the real maps
// whose corridors people filter for (skipped where ../shared/data is absent).
#include "stages/merge/area_kinds.h"

#include <gtest/gtest.h>

#include "stages/clean/clean_stage.h"
#include "stages/import/import_stage.h"
#include "tests/support/area_test_support.h"
#include "tests/support/test_support.h"
#include "tools/example_maps/floor_plan.h"

namespace areagraph::testing {
namespace {

using floorplan::RectM;
using floorplan::WallDirection;

proto::AreaKind KindAt(const AreaStages& stages, double x_m, double y_m) {
  const int area = AreaAt(stages.areas, x_m, y_m);
  EXPECT_NE(area, -1) << "no area at " << x_m << ", " << y_m;
  return area < 0 ? proto::AREA_ROOM : stages.areas.areas(area).kind();
}

AreaStages RunDrawn(const floorplan::FloorPlan& plan) {
  const proto::CleanedMap map = CleanDrawnMap(plan.image());
  AreaStages stages = RunAreaStages(map);
  ExpectAreaGraphInvariants(stages, map, 0.9);
  return stages;
}

// Offices 4 m deep along the side of `corridor` given by `above`, each with a
// 0.9 m door into it.
void DrawOffices(floorplan::FloorPlan& plan, const RectM& corridor, bool above) {
  for (double x = corridor.x; x + 4 <= corridor.x + corridor.width + 1e-9; x += 4) {
    const RectM office{x, above ? corridor.y - 4 : corridor.y + corridor.height, 4, 4};
    floorplan::DrawRoom(plan, office);
    floorplan::DrawDoor(plan, x + 2, above ? corridor.y : corridor.y + corridor.height, 0.9,
                        WallDirection::kHorizontal);
  }
}

TEST(AreaKindsTest, ACorridorLoopAroundABlockOfRoomsIsACorridor) {
  // A loop 2 m wide around a block of eight offices 16 x 8 m; offices
  // outside it above and below.
  floorplan::FloorPlan plan(21, 21);
  floorplan::DrawRegion(
      plan, {{0.5, 4.5, 20, 2}, {0.5, 14.5, 20, 2}, {0.5, 4.5, 2, 12}, {18.5, 4.5, 2, 12}});
  DrawOffices(plan, {2.5, 6.5, 16, 0}, /*above=*/false);
  DrawOffices(plan, {2.5, 14.5, 16, 0}, /*above=*/true);
  DrawOffices(plan, {0.5, 4.5, 20, 2}, /*above=*/true);
  DrawOffices(plan, {0.5, 14.5, 20, 2}, /*above=*/false);
  const AreaStages stages = RunDrawn(plan);
  EXPECT_EQ(KindAt(stages, 10, 5.5), proto::AREA_CORRIDOR);
  EXPECT_EQ(KindAt(stages, 1.5, 10.5), proto::AREA_CORRIDOR);
  EXPECT_EQ(KindAt(stages, 4.5, 8.5), proto::AREA_ROOM);
  EXPECT_EQ(KindAt(stages, 10.5, 2.5), proto::AREA_ROOM);
}

TEST(AreaKindsTest, AnLCorridorIsACorridor) {
  // An L of two arms 2 m wide and 16 m long with offices along both.
  floorplan::FloorPlan plan(23, 23);
  floorplan::DrawRegion(plan, {{0.5, 4.5, 18, 2}, {16.5, 4.5, 2, 18}});
  DrawOffices(plan, {0.5, 4.5, 16, 2}, /*above=*/true);
  DrawOffices(plan, {0.5, 4.5, 16, 2}, /*above=*/false);
  const AreaStages stages = RunDrawn(plan);
  EXPECT_EQ(KindAt(stages, 5, 5.5), proto::AREA_CORRIDOR);
  EXPECT_EQ(KindAt(stages, 17.5, 18), proto::AREA_CORRIDOR);
  EXPECT_EQ(KindAt(stages, 2.5, 2.5), proto::AREA_ROOM);
}

TEST(AreaKindsTest, AHallWithRoomsAroundItIsARoom) {
  // A hall 16 x 10 m with offices above and below: open into many areas,
  // but as wide as long.
  floorplan::FloorPlan plan(17, 19);
  floorplan::DrawRoom(plan, {0.5, 4.5, 16, 10});
  DrawOffices(plan, {0.5, 4.5, 16, 10}, /*above=*/true);
  DrawOffices(plan, {0.5, 4.5, 16, 10}, /*above=*/false);
  const AreaStages stages = RunDrawn(plan);
  EXPECT_EQ(KindAt(stages, 8.5, 9.5), proto::AREA_ROOM);
}

TEST(AreaKindsTest, ANarrowPassageBehindADoorIsADeadEnd) {
  // A corridor 2 m wide with offices above; at its right end a door 0.7 m
  // wide into a passage 1.2 m wide (1.05 m free) and 8 m long that ends: too
  // narrow for the room disk of W = 1.2 m, narrower at its door than inside
  // (no branch of the corridor), and it opens into the corridor only.
  floorplan::FloorPlan plan(26, 8);
  const RectM corridor{0.5, 4.5, 16, 2};
  floorplan::DrawRoom(plan, corridor);
  DrawOffices(plan, corridor, /*above=*/true);
  floorplan::DrawRoom(plan, {16.5, 5, 8, 1.2});
  floorplan::DrawDoor(plan, 16.5, 5.6, 0.7, WallDirection::kVertical);
  const proto::CleanedMap map = CleanDrawnMap(plan.image());
  proto::PipelineOptions options;
  options.mutable_cut()->set_room_width_m(1.2);
  const AreaStages stages = RunAreaStages(map, options);
  ExpectAreaGraphInvariants(stages, map, 0.9);
  EXPECT_EQ(KindAt(stages, 20, 5.6), proto::AREA_DEAD_END);
  EXPECT_EQ(KindAt(stages, 8, 5.5), proto::AREA_CORRIDOR);
}

// A corridor 2 m wide with offices above and, below it, small rooms too
// narrow for the room disk of W = 1.2 m (1.05 m free), kept as areas of
// their own (merge.min_area_m2 = 1): the room disk fits in none of them,
// their shapes decide.
AreaStages RunNarrowRoomsBelowACorridor(const std::vector<RectM>& rooms,
                                        const std::vector<std::pair<double, double>>& doors) {
  floorplan::FloorPlan plan(18, 14);
  const RectM corridor{0.5, 4.5, 16, 2};
  floorplan::DrawRoom(plan, corridor);
  DrawOffices(plan, corridor, /*above=*/true);
  for (const RectM& room : rooms) floorplan::DrawRoom(plan, room);
  for (const auto& [x, y] : doors) floorplan::DrawDoor(plan, x, y, 0.7, WallDirection::kHorizontal);
  const proto::CleanedMap map = CleanDrawnMap(plan.image());
  proto::PipelineOptions options;
  options.mutable_cut()->set_room_width_m(1.2);
  options.mutable_merge()->set_min_area_m2(1);
  AreaStages stages = RunAreaStages(map, options);
  ExpectAreaGraphInvariants(stages, map, 0.9);
  EXPECT_EQ(KindAt(stages, 8, 5.5), proto::AREA_CORRIDOR);
  return stages;
}

TEST(AreaKindsTest, ACupboardNarrowerThanTheRoomDiskIsARoom) {
  // 1.2 x 3 m behind a door 0.7 m wide: one exit, but too short for its
  // width to be a corridor that ends blind.
  const AreaStages stages = RunNarrowRoomsBelowACorridor({{3, 6.5, 1.2, 3}}, {{3.6, 6.5}});
  EXPECT_NE(AreaAt(stages.areas, 3.6, 8), AreaAt(stages.areas, 8, 5.5));
  EXPECT_EQ(KindAt(stages, 3.6, 8), proto::AREA_ROOM);
}

TEST(AreaKindsTest, AShortNarrowLinkBetweenTwoAreasIsARoom) {
  // A lobby 1.2 x 2 m between the corridor and an office 4 m square behind
  // it, a door at either end: a way through, but squat.
  const AreaStages stages =
      RunNarrowRoomsBelowACorridor({{8, 6.5, 1.2, 2}, {6.6, 8.5, 4, 4}}, {{8.6, 6.5}, {8.6, 8.5}});
  const int link = AreaAt(stages.areas, 8.6, 7.5);
  EXPECT_NE(link, AreaAt(stages.areas, 8, 5.5));
  EXPECT_NE(link, AreaAt(stages.areas, 8.6, 10.5));
  EXPECT_EQ(KindAt(stages, 8.6, 7.5), proto::AREA_ROOM);
}

// The maps people filter corridors on: the area that opens into the most
// others, each map's corridor system, is a corridor.
TEST(AreaKindsTest, CorridorsOfRealMapsAreCorridors) {
  if (!HaveSharedData()) GTEST_SKIP() << "no ../shared/data";
  const proto::PipelineOptions options;
  for (const char* name :
       {"areagraph/input/lab_a.png", "bormann/lab_a_scan.png", "bormann/office_d.png",
        "bormann/office_h.png", "bormann/office_i.png"}) {
    const proto::GridMap grid =
        ImportGridMap(ReadImportSource(SharedDataPath(name)), options.import());
    const AreaStages stages = RunAreaStages(CleanGridMap(grid, options.clean()), options);
    int corridor = -1;
    for (const proto::Area& area : stages.areas.areas()) {
      if (corridor < 0 ||
          area.passage_ids_size() > stages.areas.areas(corridor).passage_ids_size()) {
        corridor = area.id();
      }
    }
    ASSERT_GE(corridor, 0) << name;
    EXPECT_GE(stages.areas.areas(corridor).passage_ids_size(), 10) << name;
    EXPECT_EQ(stages.areas.areas(corridor).kind(), proto::AREA_CORRIDOR) << name;
  }
}

}  // namespace
}  // namespace areagraph::testing

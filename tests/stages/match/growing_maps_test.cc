// The whole pipeline on drawn maps that change the way a robot's map does:
// a corridor revealed room by room, a wall removed, a door closed, the same
// map again. Ids are read where the rooms are, so the test does not depend on
// how many areas the segmentation makes elsewhere.
#include <gtest/gtest.h>

#include <set>

#include "stages/pipeline/stage.h"
#include "tests/stages/match/plan_runs.h"
#include "tools/example_maps/floor_plan.h"

namespace areagraph {
namespace {

using floorplan::DrawDoor;
using floorplan::DrawRoom;
using floorplan::FloorPlan;
using floorplan::RectM;
using floorplan::WallDirection;
using testing::MatchedGraph;
using testing::RunPlan;
using testing::StableIdAt;

// A corridor (y 6..8 m) with four 5.5 m rooms above it, each with a door.
FloorPlan CorridorWithRooms() {
  FloorPlan plan(24, 10);
  DrawRoom(plan, {1, 6, 22, 2});
  for (int k = 0; k < 4; ++k) {
    DrawRoom(plan, {1 + 5.5 * k, 1.5, 5.5, 4.5});
    DrawDoor(plan, 1 + 5.5 * k + 2.75, 6, 0.9, WallDirection::kHorizontal);
  }
  return plan;
}

// What a robot in the corridor has seen after `rooms` rooms: everything left
// of the wall behind the last of them; the rest unknown.
cv::Mat Revealed(const FloorPlan& plan, int rooms) {
  cv::Mat image = plan.image().clone();
  const int seen_to = plan.ToPixels(1 + 5.5 * rooms) + plan.wall_thickness_px();
  if (seen_to < image.cols) {
    image.colRange(seen_to, image.cols).setTo(floorplan::kUnknownGrey);
  }
  return image;
}

double RoomCentreX(int k) { return 1 + 5.5 * k + 2.75; }

TEST(GrowingMapsTest, ACorridorRevealedRoomByRoomKeepsTheEarlierRoomsIds) {
  const FloorPlan plan = CorridorWithRooms();
  std::unique_ptr<ArtifactStore> store = OpenArtifactStore(":memory:");
  std::vector<int> room_ids;
  std::set<int> all_ids_so_far;
  for (int rooms = 1; rooms <= 4; ++rooms) {
    RunPlan(*store, "explored", Revealed(plan, rooms), testing::FixedWidthOptions());
    const proto::AreaGraph graph = MatchedGraph(*store, "explored");
    EXPECT_EQ(graph.version().number(), rooms);
    for (int k = 0; k < rooms - 1; ++k) {
      EXPECT_EQ(StableIdAt(graph, RoomCentreX(k), 3.5), room_ids[k])
          << "room " << k << " after " << rooms << " rooms";
    }
    const int newest = StableIdAt(graph, RoomCentreX(rooms - 1), 3.5);
    ASSERT_GE(newest, 0) << "room " << rooms - 1 << " has no area";
    // A room seen for the first time gets an id no area had before.
    EXPECT_EQ(all_ids_so_far.count(newest), 0u) << "room " << rooms - 1;
    room_ids.push_back(newest);
    for (const proto::Area& area : graph.areas()) all_ids_so_far.insert(area.stable_id());
  }
  const std::set<int> distinct(room_ids.begin(), room_ids.end());
  EXPECT_EQ(distinct.size(), 4u);
}

// Two rooms side by side, 8 m and 4 m wide, with a door between them.
FloorPlan TwoRooms() {
  FloorPlan plan(15, 8);
  DrawRoom(plan, {1, 1, 8, 6});
  DrawRoom(plan, {9, 1, 4, 6});
  DrawDoor(plan, 9, 4, 0.9, WallDirection::kVertical);
  return plan;
}

TEST(GrowingMapsTest, AWallRemovedMergesTwoAreasAndTheLargerOnesIdSurvives) {
  std::unique_ptr<ArtifactStore> store = OpenArtifactStore(":memory:");
  RunPlan(*store, "house", TwoRooms().image(), testing::FixedWidthOptions());
  const proto::AreaGraph before = MatchedGraph(*store, "house");
  const int large = StableIdAt(before, 5, 4), small = StableIdAt(before, 11, 4);
  ASSERT_GE(large, 0);
  ASSERT_GE(small, 0);
  ASSERT_NE(large, small);

  FloorPlan open(15, 8);
  DrawRoom(open, {1, 1, 12, 6});
  RunPlan(*store, "house", open.image(), testing::FixedWidthOptions());
  const proto::AreaGraph after = MatchedGraph(*store, "house");
  EXPECT_EQ(StableIdAt(after, 5, 4), large);
  EXPECT_EQ(StableIdAt(after, 11, 4), large);
  for (const proto::Area& area : after.areas()) EXPECT_NE(area.stable_id(), small);
}

TEST(GrowingMapsTest, ADoorClosedSplitsAnAreaAndTheLargerPartKeepsItsId) {
  // The rooms first open into each other through a 4 m gap: one area.
  FloorPlan wide = TwoRooms();
  DrawDoor(wide, 9, 4, 4, WallDirection::kVertical);
  std::unique_ptr<ArtifactStore> store = OpenArtifactStore(":memory:");
  RunPlan(*store, "house", wide.image(), testing::FixedWidthOptions());
  const proto::AreaGraph before = MatchedGraph(*store, "house");
  const int whole = StableIdAt(before, 5, 4);
  ASSERT_GE(whole, 0);
  ASSERT_EQ(StableIdAt(before, 11, 4), whole) << "the drawing should start as one area";

  // Then the gap is walled up but for a 0.9 m door.
  RunPlan(*store, "house", TwoRooms().image(), testing::FixedWidthOptions());
  const proto::AreaGraph after = MatchedGraph(*store, "house");
  EXPECT_EQ(StableIdAt(after, 5, 4), whole);
  const int part = StableIdAt(after, 11, 4);
  EXPECT_GE(part, before.version().next_area_id());
}

TEST(GrowingMapsTest, TheSameMapTwiceInARowPublishesTheSameGraph) {
  std::unique_ptr<ArtifactStore> store = OpenArtifactStore(":memory:");
  const FloorPlan plan = CorridorWithRooms();
  RunPlan(*store, "m", plan.image());
  std::string first_key;
  const proto::AreaGraph first = MatchedGraph(*store, "m", &first_key);
  const MapOutcome again = RunPlan(*store, "m", plan.image());
  EXPECT_TRUE(again.fully_cached);
  EXPECT_FALSE(again.graph_changed);
  std::string second_key;
  const proto::AreaGraph second = MatchedGraph(*store, "m", &second_key);
  EXPECT_EQ(second_key, first_key);
  EXPECT_EQ(second.SerializeAsString(), first.SerializeAsString());
  EXPECT_EQ(store->ReadVersions("m").size(), 1u);
}

}  // namespace
}  // namespace areagraph

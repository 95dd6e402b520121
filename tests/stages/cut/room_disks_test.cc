// Cut pass SMALL_ROOM_DISK (stages/cut/room_disks.h): with an estimated W
// that double doors lift above the free width inside a furnished office, the
// office is still one room of the Cut Graph.
#include "stages/cut/room_disks.h"

#include <gtest/gtest.h>

#include <set>

#include "tests/support/area_test_support.h"
#include "tests/support/test_support.h"
#include "tools/example_maps/floor_plan.h"

namespace areagraph::testing {
namespace {

using floorplan::RectM;
using floorplan::WallDirection;

// The furnished office: 3 x 3 m, a 1.2 m deep cupboard along its whole back
// wall, so about 1.65 m stays free, less than W.
constexpr RectM kOffice = {10.5, 6.2, 3, 3};

// A 2.2 m corridor; above it two halls behind 1.8 m double doors, below it
// four 3 x 3 m offices behind 0.9 m doors, the third one furnished. The
// estimate's widest door is 1.8 m (W 1.9 m), its median door 0.9 m.
floorplan::FloorPlan CorridorWithHallsAndOffices() {
  floorplan::FloorPlan plan(17.5, 10);
  floorplan::DrawRoom(plan, {0.5, 0.5, 8, 3.5});
  floorplan::DrawRoom(plan, {8.5, 0.5, 8, 3.5});
  floorplan::DrawRoom(plan, {0.5, 4, 16, 2.2});
  for (double x : {4.5, 7.5, 10.5, 13.5}) floorplan::DrawRoom(plan, {x, 6.2, 3, 3});
  floorplan::DrawDoor(plan, 4.5, 4, 1.8, WallDirection::kHorizontal);
  floorplan::DrawDoor(plan, 12.5, 4, 1.8, WallDirection::kHorizontal);
  for (double x : {6, 9, 12, 15})
    floorplan::DrawDoor(plan, x, 6.2, 0.9, WallDirection::kHorizontal);
  floorplan::DrawFurniture(
      plan, {kOffice.x + 0.05, kOffice.y + kOffice.height - 1.3, kOffice.width - 0.1, 1.25});
  return plan;
}

// The rooms (room_id, -1 for none) of the Cut Graph's edges whose middle
// lies in the office.
std::multiset<int> RoomsInTheOffice(const proto::CutGraph& cut, double resolution_m) {
  std::multiset<int> rooms;
  for (const proto::GraphEdge& edge : cut.edges()) {
    const proto::Point2& middle = edge.path(edge.path_size() / 2);
    const double x = middle.x() * resolution_m, y = middle.y() * resolution_m;
    if (x > kOffice.x && x < kOffice.x + kOffice.width && y > kOffice.y &&
        y < kOffice.y + kOffice.height) {
      rooms.insert(edge.room_id());
    }
  }
  return rooms;
}

AreaStages RunOnPlan(bool skip_small_disk) {
  proto::PipelineOptions options;
  if (skip_small_disk) options.mutable_cut()->add_skip_passes(proto::CutOptions::SMALL_ROOM_DISK);
  return RunAreaStages(CleanedMapFromImage(CorridorWithHallsAndOffices().image()), options);
}

TEST(SmallRoomDiskTest, TheFurnishedOfficeIsOneRoom) {
  const AreaStages stages = RunOnPlan(/*skip_small_disk=*/false);
  EXPECT_NEAR(stages.cut.room_width().room_width_m(), 1.9, 0.15);
  const std::multiset<int> rooms = RoomsInTheOffice(stages.cut, 0.05);
  ASSERT_FALSE(rooms.empty());
  EXPECT_GE(*rooms.begin(), 0) << "an edge of the office lies in no room";
  EXPECT_EQ(*rooms.begin(), *rooms.rbegin()) << "the office is split between rooms";
  // Its room is its own: the corridor's middle is in another one, or none.
  const int office = AreaAt(stages.areas, 12, 7.2);
  EXPECT_GE(office, 0);
  EXPECT_NE(office, AreaAt(stages.areas, 8, 5.1));
  EXPECT_EQ(office, AreaAt(stages.areas, 11, 6.8));
  EXPECT_EQ(office, AreaAt(stages.areas, 13, 7.4));
}

TEST(SmallRoomDiskTest, WithoutThePassTheRoomDiskFindsNoRoomInTheOffice) {
  const AreaStages stages = RunOnPlan(/*skip_small_disk=*/true);
  const std::multiset<int> rooms = RoomsInTheOffice(stages.cut, 0.05);
  ASSERT_FALSE(rooms.empty());
  EXPECT_EQ(*rooms.rbegin(), -1);
}

TEST(SmallRoomDiskTest, OnlyForAnEstimatedWidth) {
  proto::RoomWidthEstimate estimate;
  estimate.set_automatic(true);
  for (double width : {1.8, 1.8, 0.9, 0.9, 0.9, 0.9}) estimate.add_doors()->set_width_m(width);
  const proto::CutOptions defaults;
  EXPECT_NEAR(SmallRoomWidthM(defaults, estimate, 0.5), 1.0, 1e-9);
  proto::CutOptions skipped;
  skipped.add_skip_passes(proto::CutOptions::SMALL_ROOM_DISK);
  EXPECT_EQ(SmallRoomWidthM(skipped, estimate, 0.5), 0);
  estimate.set_automatic(false);
  EXPECT_EQ(SmallRoomWidthM(defaults, estimate, 0.5), 0);
}

}  // namespace
}  // namespace areagraph::testing

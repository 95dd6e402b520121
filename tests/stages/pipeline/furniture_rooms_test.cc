// A room stays one area whatever stands in it, unless a real wall divides it:
// generated rooms (the quality benchmark's furniture) run through the whole
// pipeline with the defaults.
#include <gtest/gtest.h>

#include <map>
#include <string>
#include <vector>

#include "tests/support/area_test_support.h"
#include "tools/example_maps/benchmark_furniture.h"
#include "tools/example_maps/floor_plan.h"

namespace areagraph::testing {
namespace {

using floorplan::Furnishing;
using floorplan::RectM;

// A 4.5 x 4 m room above a 1.8 m corridor, joined by a 0.9 m door; beside
// it an empty room with a 1.4 m door, so that W (above the widest door) is
// wider than most gaps between the furniture and the walls.
constexpr RectM kRoom{1, 1, 4.5, 4};
constexpr RectM kSecondRoom{5.5, 1, 4, 4};
constexpr RectM kCorridor{1, 5, 8.5, 1.8};
constexpr double kDoorX = 3, kDoorWidth = 0.9;
constexpr double kSecondDoorX = 7.5, kSecondDoorWidth = 1.4;

// The share of the room's labelled cells that its biggest area holds, and
// whether that area reaches into the corridor.
struct RoomCover {
  double biggest_share = 0;
  bool shared_with_corridor = false;
  int areas = 0;
};

RoomCover CoverOfRoom(const AreaStages& stages, const floorplan::FloorPlan& plan) {
  const cv::Rect room = floorplan::InnerCells(plan, kRoom);
  const cv::Rect corridor = floorplan::InnerCells(plan, kCorridor);
  std::map<int, int> cells;
  int total = 0;
  for (int r = room.y; r < room.br().y; ++r) {
    for (int c = room.x; c < room.br().x; ++c) {
      const int label = stages.raster.labels.at<int>(r, c);
      if (label <= 0) continue;
      ++cells[label];
      ++total;
    }
  }
  RoomCover cover;
  cover.areas = static_cast<int>(cells.size());
  int biggest = 0, count = 0;
  for (const auto& [label, n] : cells) {
    if (n > count) biggest = label, count = n;
  }
  cover.biggest_share = total > 0 ? static_cast<double>(count) / total : 0;
  for (int r = corridor.y; r < corridor.br().y; ++r) {
    for (int c = corridor.x; c < corridor.br().x; ++c) {
      cover.shared_with_corridor |= stages.raster.labels.at<int>(r, c) == biggest;
    }
  }
  return cover;
}

floorplan::FloorPlan FurnishedRoom(Furnishing furnishing, uint32_t seed) {
  floorplan::FloorPlan plan(10.5, 7.8);
  floorplan::DrawRoom(plan, kRoom);
  floorplan::DrawRoom(plan, kSecondRoom);
  floorplan::DrawRoom(plan, kCorridor);
  floorplan::DrawDoor(plan, kDoorX, kCorridor.y, kDoorWidth, floorplan::WallDirection::kHorizontal);
  floorplan::DrawDoor(plan, kSecondDoorX, kCorridor.y, kSecondDoorWidth,
                      floorplan::WallDirection::kHorizontal);
  const double wall_m = plan.wall_thickness_px() * plan.resolution_m();
  const std::vector<RectM> keep_out{
      {kDoorX - kDoorWidth / 2 - 0.3, kCorridor.y - 1.1, kDoorWidth + 0.6, 2.2}};
  floorplan::PortableRandom random(seed);
  for (const RectM& item : floorplan::FurnishRoom(floorplan::InnerRect(kRoom, wall_m), furnishing,
                                                  keep_out, /*clutter=*/false, random)) {
    floorplan::DrawFurniture(plan, item);
  }
  return plan;
}

struct Case {
  const char* name;
  Furnishing furnishing;
  uint32_t seed;
};

class FurnitureRoomTest : public ::testing::TestWithParam<Case> {};

TEST_P(FurnitureRoomTest, RoomStaysOneArea) {
  const floorplan::FloorPlan plan = FurnishedRoom(GetParam().furnishing, GetParam().seed);
  const proto::CleanedMap map = CleanDrawnMap(plan.image());
  const AreaStages stages = RunAreaStages(map);
  const RoomCover cover = CoverOfRoom(stages, plan);
  EXPECT_GE(cover.biggest_share, 0.97) << cover.areas << " areas in the room";
  EXPECT_FALSE(cover.shared_with_corridor);
}

std::vector<Case> Cases() {
  std::vector<Case> cases;
  for (uint32_t seed = 1; seed <= 8; ++seed) {
    cases.push_back({"OneDesk", Furnishing::kOneDesk, seed});
    cases.push_back({"SeveralDesks", Furnishing::kSeveralDesks, seed});
    cases.push_back({"CabinetByWall", Furnishing::kCabinetByWall, seed});
    cases.push_back({"DeskRing", Furnishing::kDeskRing, seed});
  }
  return cases;
}

INSTANTIATE_TEST_SUITE_P(GeneratedRooms, FurnitureRoomTest, ::testing::ValuesIn(Cases()),
                         [](const ::testing::TestParamInfo<Case>& info) {
                           return std::string(info.param.name) + "Seed" +
                                  std::to_string(info.param.seed);
                         });

TEST(FurnitureRoomTest, WithoutIslandsAndRoomJoiningSomeRoomsSplit) {
  // The cases are not trivial: with every obstacle stopping the room disk
  // (the paper), no room joining and no joining at furniture gaps, desks
  // split some of the rooms.
  proto::PipelineOptions options;
  options.mutable_cut()->add_skip_passes(proto::CutOptions::FREE_STANDING_ISLANDS);
  options.mutable_merge()->add_skip_passes(proto::MergeOptions::JOIN_ROOMS_WITHOUT_DOORS);
  options.mutable_merge()->add_skip_passes(proto::MergeOptions::JOIN_FURNITURE_GAPS);
  int split = 0;
  for (const Case& c : Cases()) {
    const floorplan::FloorPlan plan = FurnishedRoom(c.furnishing, c.seed);
    const RoomCover cover = CoverOfRoom(RunAreaStages(CleanDrawnMap(plan.image()), options), plan);
    if (cover.biggest_share < 0.97) ++split;
  }
  EXPECT_GE(split, 3);
}

TEST(FurnitureRoomTest, RealWallStillDividesTheRoom) {
  // The room cut in two by a wall at x = 3.5 m with a 0.9 m door: two rooms.
  floorplan::FloorPlan plan = FurnishedRoom(Furnishing::kEmpty, 1);
  floorplan::DrawRoom(plan, {1, 1, 2.5, 4});
  floorplan::DrawDoor(plan, 3.5, 2.5, 0.9, floorplan::WallDirection::kVertical);
  floorplan::DrawDoor(plan, 2.2, kCorridor.y, kDoorWidth, floorplan::WallDirection::kHorizontal);
  floorplan::DrawDoor(plan, 4.5, kCorridor.y, kDoorWidth, floorplan::WallDirection::kHorizontal);
  const proto::CleanedMap map = CleanDrawnMap(plan.image());
  const AreaStages stages = RunAreaStages(map);
  ExpectAreaGraphInvariants(stages, map, 0.9);
  const int left = AreaAt(stages.areas, 2.2, 2.5), right = AreaAt(stages.areas, 4.5, 2.5);
  EXPECT_NE(left, -1);
  EXPECT_NE(right, -1);
  EXPECT_NE(left, right);
}

}  // namespace
}  // namespace areagraph::testing

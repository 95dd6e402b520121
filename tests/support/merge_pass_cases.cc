#include "tests/support/merge_pass_cases.h"

namespace areagraph::testing {

using floorplan::DrawDoor;
using floorplan::DrawFurniture;
using floorplan::DrawRegion;
using floorplan::DrawRoom;
using floorplan::FloorPlan;
using floorplan::RectM;
using floorplan::WallDirection;
using Options = proto::MergeOptions;

namespace {

// The corridor under the offices of CorridorWithStubs and CorridorWithStem:
// 2.2 m between wall centres.
constexpr double kCorridorY = 4.5;
constexpr double kCorridorHeight = 2.2;
constexpr double kCorridorMiddleY = kCorridorY + kCorridorHeight / 2;

// A corridor 20 m long, 1.35 m between its walls, under five offices with
// 0.9 m doors. A fixed W of 1.5 m does not fit in it: the Topology Graph
// cuts it into a room-less piece at every office's door.
MergePassCase CorridorCutAtDoors() {
  FloorPlan plan(21, 6.5);
  DrawRoom(plan, {0.5, kCorridorY, 20, 1.5});
  DrawOffices(plan, 20, 4, kCorridorY);
  return {"a corridor cut at its side doors is one corridor",
          plan,
          FixedRoomWidth(1.5),
          {3, 5.25},
          {{17, 5.25}}};
}

// A room 5 x 2.2 m (2.05 m between its walls) that two wall stubs narrow by
// 0.075 m each at x = 3 m: W = 2 m fits in the room but not between the
// stubs, which leave 93 % of the room's width open.
MergePassCase RoomNarrowedByStubs() {
  FloorPlan plan(6, 3.2);
  DrawRoom(plan, {0.5, 0.5, 5, 2.2});
  DrawFurniture(plan, {2.85, 0.5, 0.3, 0.15});
  DrawFurniture(plan, {2.85, 2.55, 0.3, 0.15});
  return {"a room that W splits at a slight narrowing is one room",
          plan,
          FixedRoomWidth(2),
          {1.5, 1.6},
          {{4.5, 1.6}}};
}

MergePassCase CabinetAcrossARoom() {
  return {"a cabinet across a room does not split it",
          RoomWithDivider(kCabinetAcrossRoom),
          {},
          {2, 3},
          {{5, 3}}};
}

// The default W (1.25 m) does not fit in the bay, and no small area folds:
// only bay folding joins it to the room.
MergePassCase OpenBay() {
  proto::PipelineOptions options;
  options.mutable_cut()->set_room_width_m(1.25);
  options.mutable_merge()->set_min_area_m2(0);
  return {"a bay open over its whole width is part of its room",
          RoomWithOpenBay(),
          options,
          {3.05, 6.2},
          {{3.5, 2.5}}};
}

// A corridor 20 m long and 0.85 m between its walls that widens to a square
// of 2 x 2 m at x = 9-11 m: W = 1.5 m fits only there and makes a small room
// that opens into the corridor over its whole width on both sides.
MergePassCase CorridorWithAWideSpot() {
  FloorPlan plan(21, 5);
  DrawRegion(plan, {{0.5, 2, 20, 1}, {9, 1.5, 2, 2}});
  return {"a wide spot of a corridor is part of the corridor",
          plan,
          FixedRoomWidth(1.5),
          {10, 2.5},
          {{3, 2.5}, {17, 2.5}}};
}

// A 10 x 6 m room with a row of three shelves 0.4 m deep down its middle
// (x = 5 m), leaving gaps of 0.4 m (at the top wall), 0.8 m and 0.8 m: all
// narrower than W, one of them too narrow to walk through.
MergePassCase RowOfShelves() {
  FloorPlan plan(11, 7);
  DrawRoom(plan, {0.5, 0.5, 10, 6});
  constexpr double kWallM = 0.15, kFirstGapM = 0.4, kGapM = 0.8;
  constexpr int kShelves = 3;
  const double length = (6 - kWallM - kFirstGapM - kGapM * (kShelves - 1)) / kShelves;
  double y = 0.5 + kWallM / 2 + kFirstGapM;
  for (int k = 0; k < kShelves; ++k, y += length + kGapM) DrawFurniture(plan, {5, y, 0.4, length});
  return {"a row of shelves with a narrow gap does not split a room", plan, {}, {2, 3}, {{8, 3}}};
}

// W = 1.9 m (as an automatic W near the corridor's width comes out) does not
// pass between the stubs, and the corridor falls into two room-shaped pieces.
MergePassCase CorridorSplitAtStubs() {
  return {"a corridor that W split at a narrowing is one corridor",
          CorridorWithStubs(),
          FixedRoomWidth(1.9),
          {5, kCorridorMiddleY},
          {{26, kCorridorMiddleY}}};
}

// W = 1.5 m does not fit in the branch: a room-less dead end.
MergePassCase BranchOfACorridor() {
  return {"a dead-end branch as wide as its mouth is part of its corridor",
          CorridorWithStem(),
          FixedRoomWidth(1.5),
          {7, 9.5},
          {{3, kCorridorMiddleY}}};
}

// The closet (1.4 m2) is smaller than merge.min_area_m2.
MergePassCase ClosetBehindADoor() {
  return {"a closet behind a door the cut closed stays an area of its own",
          RoomAndCloset(),
          {},
          {7.1, 1.25},
          {{3.5, 3}},
          /*joined=*/false};
}

// Six rows of seats, each too long and thin for a furniture island: without
// the pass the strips between them are areas of their own.
MergePassCase LectureHall() {
  return {"a lecture hall's rows of seats do not cut it into strips",
          HallWithSeatRows(6),
          {},
          {7, 2.5},
          {{7, kFirstSeatRowY + 2 * kSeatRowPitch + 0.8}}};
}

}  // namespace

std::optional<MergePassCase> CaseOfMergePass(proto::MergeOptions::Pass pass) {
  switch (pass) {
    case Options::JOIN_CORRIDOR_PIECES:
      return CorridorCutAtDoors();
    case Options::JOIN_ROOMS_WITHOUT_DOORS:
      return RoomNarrowedByStubs();
    case Options::JOIN_FURNITURE_GAPS:
      return CabinetAcrossARoom();
    case Options::JOIN_FURNITURE_ROWS:
      return LectureHall();
    case Options::FOLD_OPEN_BAYS:
      return OpenBay();
    case Options::FOLD_CORRIDOR_PIECES:
      return CorridorWithAWideSpot();
    case Options::JOIN_POROUS_BORDERS:
      return RowOfShelves();
    case Options::JOIN_SPLIT_CORRIDORS:
      return CorridorSplitAtStubs();
    case Options::JOIN_CORRIDOR_STEMS:
      return BranchOfACorridor();
    case Options::KEEP_SMALL_CLOSED_ROOMS:
      return ClosetBehindADoor();
    default:
      return std::nullopt;
  }
}

proto::PipelineOptions FixedRoomWidth(double room_width_m) {
  proto::PipelineOptions options;
  options.mutable_cut()->set_room_width_m(room_width_m);
  return options;
}

FloorPlan RoomWithDivider(const RectM& divider) {
  constexpr RectM kRoom{1, 1, 5, 4};
  constexpr RectM kOffice{6, 1, 4, 4};
  constexpr RectM kCorridor{1, 5, 9, 1.8};
  FloorPlan plan(11, 7.8);
  DrawRoom(plan, kRoom);
  DrawRoom(plan, kOffice);
  DrawRoom(plan, kCorridor);
  DrawDoor(plan, 2, kCorridor.y, 0.9, WallDirection::kHorizontal);
  DrawDoor(plan, 8, kCorridor.y, 0.9, WallDirection::kHorizontal);
  DrawFurniture(plan, divider);
  return plan;
}

FloorPlan RoomWithOpenBay() {
  FloorPlan plan(7, 7.5);
  DrawRegion(plan, {{0.5, 0.5, 6, 4}, {2.5, 4.0, 1.1, 3.0}});
  return plan;
}

void DrawOffices(FloorPlan& plan, double length_m, double office_m, double corridor_y_m) {
  for (double x = 0.5; x + office_m <= 0.5 + length_m + 1e-9; x += office_m) {
    DrawRoom(plan, {x, 0.5, office_m, 4});
    DrawDoor(plan, x + office_m / 2, corridor_y_m, 0.9, WallDirection::kHorizontal);
  }
}

FloorPlan CorridorWithStubs() {
  FloorPlan plan(31, 7.5);
  DrawOffices(plan, 30, 5, kCorridorY);
  const RectM corridor{0.5, kCorridorY, 30, kCorridorHeight};
  DrawRoom(plan, corridor);
  DrawFurniture(plan, {15.35, corridor.y, 0.3, 0.25});
  DrawFurniture(plan, {15.35, corridor.y + corridor.height - 0.25, 0.3, 0.25});
  return plan;
}

FloorPlan CorridorWithStem() {
  FloorPlan plan(21, 13.5);
  DrawRoom(plan, {0.5, kCorridorY, 20, kCorridorHeight});
  DrawOffices(plan, 20, 5, kCorridorY);
  const double below = kCorridorY + kCorridorHeight;
  DrawRoom(plan, {6.4, below, 1.2, 6});
  DrawDoor(plan, 7, below, 1.05, WallDirection::kHorizontal);  // no narrowing
  DrawRoom(plan, {15, below, 1.2, 4.5});
  DrawDoor(plan, 15.6, below, 0.7, WallDirection::kHorizontal);
  return plan;
}

FloorPlan RoomAndCloset(bool far_wall_unknown) {
  FloorPlan plan(8.6, 6);
  DrawRoom(plan, {0.5, 0.5, 6, 5});
  DrawRoom(plan, {6.5, 0.5, 1.2, 1.5});
  DrawDoor(plan, 6.5, 1.25, 0.8, WallDirection::kVertical);
  if (far_wall_unknown) {
    const cv::Rect inner = floorplan::InnerCells(plan, {6.5, 0.5, 1.2, 1.5});
    plan.image()(cv::Rect(inner.br().x, inner.y, plan.wall_thickness_px(), inner.height))
        .setTo(floorplan::kUnknownGrey);
  }
  return plan;
}

FloorPlan HallWithSeatRows(int rows) {
  constexpr RectM kHall{1, 1, 12, 12};
  constexpr RectM kOffice{13, 1, 4, 4};
  constexpr RectM kCorridor{1, 13, 16, 2};
  constexpr double kAisle = 1.2, kSeatDepth = 0.5;
  FloorPlan plan(18, 16);
  DrawRoom(plan, kHall);
  DrawRoom(plan, kOffice);
  DrawRoom(plan, kCorridor);
  DrawDoor(plan, 6, kCorridor.y, 1.2, WallDirection::kHorizontal);
  DrawDoor(plan, 14, kCorridor.y, 0.9, WallDirection::kHorizontal);
  // A way through the hall into the office: the hall has two exits, as a
  // corridor has.
  DrawDoor(plan, kOffice.x, 2, 0.9, WallDirection::kVertical);
  for (int k = 0; k < rows; ++k) {
    DrawFurniture(plan, {kHall.x + kAisle, kFirstSeatRowY + k * kSeatRowPitch,
                         kHall.width - 2 * kAisle, kSeatDepth});
  }
  return plan;
}

}  // namespace areagraph::testing

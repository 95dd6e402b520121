// A strip above a room, divided by a wall with two doors 1 m wide: the piece
// of wall between the doors stands free. clean pass KEEP_WALL_PIECES: a thin piece
// (1.6 x 0.15 m) has a desk's perimeter, and furniture removal took it out,
// so the strip and the room became one (areagraph/ lab_d_scan_furnitures).
// merge.furniture_gaps.max_elongation: a thick piece (2.4 x 0.4 m) stays and
// divides them too (with any shape allowed ag-merge took such a piece for a
// desk and joined the two at its doors on areagraph/ lab_d; that the limit
// refuses it is tested in tests/stages/merge/corridor_labels_test.cc).
#include <gtest/gtest.h>

#include "tests/support/area_test_support.h"
#include "tools/example_maps/floor_plan.h"

namespace areagraph::testing {
namespace {

using floorplan::WallDirection;

// The strip {0.5, 0.5, 6, 2.5} above the room {0.5, 3, 6, 5}; the doors in
// the wall between them (y = 3 m) are free from 1.25 to 2.25 m and from
// `second_door_m` to `second_door_m` + 1 m.
floorplan::FloorPlan StripAndRoom(double second_door_m) {
  floorplan::FloorPlan plan(7, 8.5);
  floorplan::DrawRoom(plan, {0.5, 0.5, 6, 2.5});
  floorplan::DrawRoom(plan, {0.5, 3, 6, 5});
  floorplan::DrawDoor(plan, 1.75, 3, 1.0, WallDirection::kHorizontal);
  floorplan::DrawDoor(plan, second_door_m + 0.5, 3, 1.0, WallDirection::kHorizontal);
  return plan;
}

struct Result {
  int strip = -1, room = -1;
};

Result RunOn(const floorplan::FloorPlan& plan, const proto::PipelineOptions& options) {
  const proto::CleanedMap map = CleanDrawnMap(plan.image(), options.clean());
  const AreaStages stages = RunAreaStages(map, options);
  ExpectAreaGraphInvariants(stages, map, 0.9);
  return {AreaAt(stages.areas, 3.5, 1.75), AreaAt(stages.areas, 3.5, 5.5)};
}

// The thin piece: 1.6 m of the 0.15 m wall, from 2.25 to 3.85 m.
floorplan::FloorPlan ThinPiece() { return StripAndRoom(3.85); }

// The thick piece: 2.4 m long and 0.4 m thick, from 2.25 to 4.65 m.
floorplan::FloorPlan ThickPiece() {
  floorplan::FloorPlan plan = StripAndRoom(4.65);
  floorplan::DrawFurniture(plan, {2.25, 2.8, 2.4, 0.4});
  return plan;
}

TEST(WallPiecesTest, AThinPieceOfWallBetweenTwoDoorsStays) {
  const Result result = RunOn(ThinPiece(), {});
  ASSERT_NE(result.strip, -1);
  ASSERT_NE(result.room, -1);
  EXPECT_NE(result.strip, result.room);
}

TEST(WallPiecesTest, WithoutKeepWallPiecesFurnitureRemovalTakesItAndJoinsTheTwo) {
  proto::PipelineOptions options;
  options.mutable_clean()->add_skip_passes(proto::CleanOptions::KEEP_WALL_PIECES);
  const proto::CleanedMap map = CleanDrawnMap(ThinPiece().image(), options.clean());
  EXPECT_GT(map.removed_furniture_cells_size(), 0);
  const Result result = RunOn(ThinPiece(), options);
  ASSERT_NE(result.strip, -1);
  EXPECT_EQ(result.strip, result.room);
}

// As on lab_d, where the cut closed neither door (here it would, and merge
// joins nothing at a closed door: ClosedVertices).
proto::PipelineOptions DoorsLeftOpen() {
  proto::PipelineOptions options;
  options.mutable_cut()->add_skip_passes(proto::CutOptions::CLOSE_WALL_DOORS);
  options.mutable_cut()->add_skip_passes(proto::CutOptions::CLOSE_WALL_GAPS);
  return options;
}

TEST(WallPiecesTest, AThickPieceOfWallIsNoFurnitureIsland) {
  const Result result = RunOn(ThickPiece(), DoorsLeftOpen());
  ASSERT_NE(result.strip, -1);
  ASSERT_NE(result.room, -1);
  EXPECT_NE(result.strip, result.room);
}

}  // namespace
}  // namespace areagraph::testing

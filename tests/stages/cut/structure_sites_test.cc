// StructureSites on drawn plans: a free-standing block is an island (its
// sites are dropped for the room disk); a block that a wall stub continues
// end-on is a piece of a dividing row and keeps its sites, also when the stub
// is just beside the block's centre line, but not
// when only the edge of its face lines up with the stub (a desk beside a door
// jamb or a cabinet: cut.islands.end_on_face_share).
#include "stages/cut/structure_sites.h"

#include <gtest/gtest.h>

#include "tests/support/area_test_support.h"
#include "tools/example_maps/floor_plan.h"

namespace areagraph::testing {
namespace {

using floorplan::FloorPlan;

constexpr double kResolutionM = 0.05;
// The block: 1.0 m wide, 2.0 m long, standing free in a 7 x 6 m room with
// four narrow rooms beside it (their walls set the map's typical wall).
constexpr floorplan::RectM kBlock{2.9, 3.3, 1.0, 2.0};

FloorPlan RoomWithBlock() {
  FloorPlan plan(12.2, 6.2, kResolutionM);
  floorplan::DrawRoom(plan, {0.1, 0.1, 7, 6});
  for (int k = 0; k < 4; ++k) floorplan::DrawRoom(plan, {7.1 + 1.25 * k, 0.1, 1.25, 6});
  floorplan::DrawFurniture(plan, kBlock);
  return plan;
}

// How many of the structure sites lie on the block.
int SitesOnBlock(const FloorPlan& plan, double end_on_face_share, bool both_ends = true) {
  const proto::CleanedMap map = CleanDrawnMap(plan.image());
  const PointList sites =
      StructureSites(map.cells(), map.frame().width_px(), map.frame().height_px(), kResolutionM,
                     /*max_island_m=*/4.0, end_on_face_share, both_ends,
                     LabelObstacles(map.cells(), map.frame().width_px(), map.frame().height_px()));
  int on_block = 0;
  for (const Eigen::Vector2d& site : sites) {
    const double x = site.x() * kResolutionM, y = site.y() * kResolutionM;
    on_block += x > kBlock.x - 0.05 && x < kBlock.x + kBlock.width + 0.05 && y > kBlock.y - 0.05 &&
                y < kBlock.y + kBlock.height + 0.05;
  }
  return on_block;
}

// The face shares tried: centre line only (a share of 0), the
// default middle quarter, and the whole face (cut 7's option).
constexpr double kCentreLine = 0, kMiddleQuarter = 0.25, kWholeFace = 1;

TEST(StructureSitesTest, FreeStandingBlockIsAnIsland) {
  for (const double share : {kCentreLine, kMiddleQuarter, kWholeFace}) {
    EXPECT_EQ(SitesOnBlock(RoomWithBlock(), share), 0) << share;
  }
}

TEST(StructureSitesTest, BlockContinuedByAWallStubBesideItsCentreLineIsStructure) {
  // A 0.15 m wall stub from the top wall down to y = 2.0 m, 1.3 m above the
  // block, 0.05 m beside its centre line (x 3.2-3.35 m; the centre line is
  // x = 3.4 m): a row that divides the room, with a gap in it.
  FloorPlan plan = RoomWithBlock();
  floorplan::DrawFurniture(plan, {3.2, 0.1, 0.15, 1.9});
  EXPECT_GT(SitesOnBlock(plan, kMiddleQuarter), 40);
  EXPECT_GT(SitesOnBlock(plan, kWholeFace), 40);
  EXPECT_EQ(SitesOnBlock(plan, kCentreLine), 0);
}

TEST(StructureSitesTest, BlockWhoseFaceEdgeLinesUpWithAStubStaysAnIsland) {
  // The same stub over the block's left edge (x 3.0-3.15 m), as a door's
  // jamb or a cabinet's side lines up with a desk's edge: only the whole
  // face (cut 7's option) takes the desk for a piece of wall.
  FloorPlan plan = RoomWithBlock();
  floorplan::DrawFurniture(plan, {3.0, 0.1, 0.15, 1.9});
  EXPECT_EQ(SitesOnBlock(plan, kMiddleQuarter), 0);
  EXPECT_EQ(SitesOnBlock(plan, kCentreLine), 0);
  EXPECT_GT(SitesOnBlock(plan, kWholeFace), 40);
}

TEST(StructureSitesTest, BlockWithAStubOnItsCentreLineIsStructureEitherWay) {
  FloorPlan plan = RoomWithBlock();
  floorplan::DrawFurniture(plan, {3.325, 0.1, 0.15, 1.9});
  for (const double share : {kCentreLine, kMiddleQuarter, kWholeFace}) {
    EXPECT_GT(SitesOnBlock(plan, share), 40) << share;
  }
}

TEST(StructureSitesTest, BlockContinuedAtOneEndOnlyIsAnIsland) {
  // A cabinet 0.5 x 1 m against the top wall on the block's centre line,
  // 0.6 m above a block moved up to y = 1.7-3.7 m: its other end is 2.4 m
  // from the bottom wall, wider than a door, so it is no piece of wall
  // between two doors (cut pass WALL_PIECES_NEED_BOTH_ENDS); one continued end
  // was enough before.
  FloorPlan plan(12.2, 6.2, kResolutionM);
  floorplan::DrawRoom(plan, {0.1, 0.1, 7, 6});
  for (int k = 0; k < 4; ++k) floorplan::DrawRoom(plan, {7.1 + 1.25 * k, 0.1, 1.25, 6});
  floorplan::DrawFurniture(plan, {3.15, 0.1, 0.5, 1.0});
  floorplan::DrawFurniture(plan, {kBlock.x, 1.7, kBlock.width, kBlock.height});
  const auto sites_on_moved_block = [&](bool both_ends) {
    const proto::CleanedMap map = CleanDrawnMap(plan.image());
    int on_block = 0;
    for (const Eigen::Vector2d& site : StructureSites(
             map.cells(), map.frame().width_px(), map.frame().height_px(), kResolutionM, 4.0,
             kMiddleQuarter, both_ends,
             LabelObstacles(map.cells(), map.frame().width_px(), map.frame().height_px()))) {
      const double x = site.x() * kResolutionM, y = site.y() * kResolutionM;
      on_block += x > kBlock.x - 0.05 && x < kBlock.x + kBlock.width + 0.05 && y > 1.65 && y < 3.75;
    }
    return on_block;
  };
  EXPECT_EQ(sites_on_moved_block(true), 0);
  EXPECT_GT(sites_on_moved_block(false), 40);
}

}  // namespace
}  // namespace areagraph::testing

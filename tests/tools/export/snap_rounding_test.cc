// Snap rounding onto OSM's grid: edges are routed through the hot pixels
// they pass, so that rounding never makes rings cross.
#include "tools/export/snap_rounding.h"

#include <gtest/gtest.h>

#include <vector>

namespace areagraph {
namespace {

using Points = std::vector<GridPoint>;

// Edge e of a ring runs from (0, 0.3) to (10, 1.3), a triangle's apex lies
// 0.05 below it at (5, 0.75). Rounding the vertices alone gives e from (0, 0)
// to (10, 1), half a unit below the apex's (5, 1): the triangle would poke
// through the ring. Routed through the apex's hot pixel, e bends to touch it.
TEST(SnapRounder, RoutesAnEdgeThroughAVertexItPassesNear) {
  const std::vector<std::vector<GridPosition>> rings = {{{0, 0.3}, {10, 1.3}, {10, 10}, {0, 10}},
                                                        {{2, -5}, {8, -5}, {5, 0.75}}};
  const SnapRounder snap(rings);
  EXPECT_EQ(snap.Ring(rings[0]), (Points{{0, 0}, {5, 1}, {10, 1}, {10, 10}, {0, 10}}));
  EXPECT_EQ(snap.Ring(rings[1]), (Points{{2, -5}, {8, -5}, {5, 1}}));
  // A line along the same edge is routed alike.
  EXPECT_EQ(snap.Line({{0, 0.3}, {10, 1.3}}), (Points{{0, 0}, {5, 1}, {10, 1}}));
}

TEST(SnapRounder, LeavesEdgesAwayFromOtherVerticesStraight) {
  const std::vector<std::vector<GridPosition>> rings = {{{0.2, 0.1}, {20.4, -0.3}, {9.6, 30.2}}};
  EXPECT_EQ(SnapRounder(rings).Ring(rings[0]), (Points{{0, 0}, {20, 0}, {10, 30}}));
}

// Two vertices in one grid cell become one point: consecutive ones repeat it,
// the rest of a neck narrower than the grid visits it twice.
TEST(SnapRounder, VerticesInOneCellMeet) {
  const std::vector<std::vector<GridPosition>> rings = {
      {{0, 0}, {10, 4.9}, {20, 0}, {20, 10}, {10, 5.1}, {10.2, 5.05}, {0, 10}}};
  EXPECT_EQ(SnapRounder(rings).Ring(rings[0]),
            (Points{{0, 0}, {10, 5}, {20, 0}, {20, 10}, {10, 5}, {10, 5}, {0, 10}}));
}

}  // namespace
}  // namespace areagraph

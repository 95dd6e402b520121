// Cut's room shape on OpenCV's pool (the sites' spatial sort beside the
// insertion of its first quarter, DetectRooms' member tests over ranges of
// the faces): the same rooms, areas, walks and outlines on one thread and on
// two.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "stages/geometry/site_alpha_shape.h"
#include "tests/support/thread_count.h"

namespace areagraph {
namespace {

using testing::ThreadCount;

constexpr int kRoomPx = 30;
constexpr int kCols = 24, kRows = 18;

// A grid of rooms: cell-centre sites along every wall, a door gap in each
// wall but the outer ones, and a closed door (sites off the half grid, as
// cut's closing sites) in every third.
PointList RoomSites() {
  PointList sites;
  const int width = kCols * kRoomPx, height = kRows * kRoomPx;
  for (int line = 0; line <= kRows; ++line) {
    const double y = line * kRoomPx + 0.5;
    for (int x = 0; x < width; ++x) {
      const int along = x % kRoomPx;
      const bool door = line > 0 && line < kRows && along >= 12 && along < 18;
      if (!door) sites.emplace_back(x + 0.5, y);
      if (door && (x / kRoomPx + line) % 3 == 0) sites.emplace_back(x + 0.5 + 0.3, y + 0.21);
    }
  }
  for (int line = 0; line <= kCols; ++line) {
    const double x = line * kRoomPx + 0.5;
    for (int y = 1; y < height; ++y) {
      const int along = y % kRoomPx;
      if (along == 0) continue;
      const bool door = line > 0 && line < kCols && along >= 8 && along < 14;
      if (!door) sites.emplace_back(x, y + 0.5);
    }
  }
  return sites;
}

struct Rooms {
  int count = 0;
  std::vector<double> areas;
  std::vector<int> at;
  std::string outlines;
};

Rooms RoomsOf(const PointList& sites) {
  SiteAlphaShape shape(sites, 7.0);
  Rooms rooms;
  // The right eighth lies outside the boundary.
  rooms.count =
      shape.DetectRooms([](const Eigen::Vector2d& p) { return p.x() < kCols * kRoomPx * 7 / 8; });
  rooms.areas = shape.RoomAreas();
  // Cell centres and cell corners (on Delaunay edges of the grid sites).
  for (double y = 1; y < kRows * kRoomPx; y += 3.5) {
    for (double x = 1; x < kCols * kRoomPx; x += 2.5) rooms.at.push_back(shape.RoomAt({x, y}));
  }
  for (const proto::Polygon& outline : shape.RoomOutlines()) {
    rooms.outlines += outline.SerializeAsString();
  }
  return rooms;
}

TEST(RoomShapeThreadsTest, OneAndTwoThreadsGiveTheSameRooms) {
  const PointList sites = RoomSites();
  // Over 8 192 sites (the sort's tasks) and twice 16 384 faces (two ranges).
  ASSERT_GT(sites.size(), 20000u);
  Rooms one, two;
  {
    const ThreadCount threads(1);
    one = RoomsOf(sites);
  }
  {
    const ThreadCount threads(2);
    two = RoomsOf(sites);
  }
  // Every room but the cut-off column and the doors closed on purpose.
  EXPECT_GT(one.count, kCols * kRows / 2);
  EXPECT_EQ(one.count, two.count);
  EXPECT_EQ(one.areas, two.areas);
  EXPECT_EQ(one.at, two.at);
  EXPECT_TRUE(one.outlines == two.outlines);
  EXPECT_FALSE(one.outlines.empty());
}

}  // namespace
}  // namespace areagraph

// The triangulation that ag-voronoi keeps for ag-prune in one process
// (stages/geometry/site_triangulation.h): it is given back only for the same
// sites and only once, and a shape on it is the shape on a new one.
#include "stages/geometry/site_triangulation.h"

#include <google/protobuf/util/message_differencer.h>
#include <gtest/gtest.h>

#include <random>

#include "stages/geometry/site_alpha_shape.h"
#include "stages/geometry/site_triangulation_cgal.h"

namespace areagraph {
namespace {

// Grid cells of two walled rooms with a door between them and random
// obstacle cells inside: many co-circular sites, whose triangulation depends
// on the insertion.
PointList RoomsWithClutter() {
  PointList sites;
  auto wall = [&](int x0, int y0, int x1, int y1) {
    for (int x = x0; x <= x1; ++x) {
      for (int y = y0; y <= y1; ++y) sites.emplace_back(x + 0.5, y + 0.5);
    }
  };
  wall(0, 0, 60, 0);
  wall(0, 30, 60, 30);
  wall(0, 1, 0, 29);
  wall(60, 1, 60, 29);
  wall(30, 1, 30, 12);  // the dividing wall, a door from 13 to 17
  wall(30, 18, 30, 29);
  std::mt19937 random(7);
  std::uniform_int_distribution<int> x(2, 58), y(2, 28);
  for (int i = 0; i < 40; ++i) sites.emplace_back(x(random) + 0.5, y(random) + 0.5);
  return sites;
}

void ExpectSameShape(SiteAlphaShape& a, SiteAlphaShape& b) {
  const std::vector<double> areas = a.FindEnclosedRegions();
  ASSERT_EQ(b.FindEnclosedRegions(), areas);
  ASSERT_GE(areas.size(), 1u);
  for (int region = 0; region < static_cast<int>(areas.size()); ++region) {
    EXPECT_TRUE(google::protobuf::util::MessageDifferencer::Equals(a.EnclosedRegionOutline(region),
                                                                   b.EnclosedRegionOutline(region)))
        << "region " << region;
  }
  for (const Eigen::Vector2d& p : {Eigen::Vector2d(10.2, 10.7), Eigen::Vector2d(45.5, 20.1)}) {
    EXPECT_EQ(a.EnclosedRegionAt(p), b.EnclosedRegionAt(p));
  }
  auto everywhere = [](const Eigen::Vector2d&) { return true; };
  ASSERT_EQ(a.DetectRooms(everywhere), b.DetectRooms(everywhere));
  EXPECT_EQ(a.RoomAreas(), b.RoomAreas());
  const std::vector<proto::Polygon> rooms = a.RoomOutlines();
  const std::vector<proto::Polygon> other_rooms = b.RoomOutlines();
  ASSERT_EQ(rooms.size(), other_rooms.size());
  ASSERT_GE(rooms.size(), 2u) << "the door should part two rooms";
  for (size_t r = 0; r < rooms.size(); ++r) {
    EXPECT_TRUE(google::protobuf::util::MessageDifferencer::Equals(rooms[r], other_rooms[r]))
        << "room " << r;
  }
}

// The integer in-circle test of sites on the half-pixel grid gives Epick's
// (exact) signs, co-circular quadruples (zero) included, near the range's end
// too.
TEST(SiteTriangulationTest, TheHalfGridInCircleTestIsEpicks) {
  const site_cgal::Traits half_grid(true);
  const auto fast = half_grid.side_of_oriented_circle_2_object();
  const auto epick = site_cgal::Kernel().side_of_oriented_circle_2_object();
  std::mt19937 random(5);
  int zeros = 0;
  for (const double offset : {0.0, site_cgal::Traits::kHalfGridLimit - 64}) {
    for (const int span : {6, 40, 4000}) {
      std::uniform_int_distribution<int> cell(0, span);
      auto site = [&] { return site_cgal::Point(offset + cell(random) + 0.5, cell(random) + 0.5); };
      for (int i = 0; i < 20000; ++i) {
        const site_cgal::Point p = site(), q = site(), r = site(), t = site();
        const CGAL::Oriented_side expected = epick(p, q, r, t);
        ASSERT_EQ(fast(p, q, r, t), expected) << p << " " << q << " " << r << " " << t;
        zeros += expected == CGAL::ON_ORIENTED_BOUNDARY;
      }
    }
  }
  EXPECT_GT(zeros, 1000) << "too few co-circular quadruples to mean anything";
}

TEST(SiteTriangulationTest, TheIndexedTriangulationGivesTheSameShapeAsANewOne) {
  const PointList sites = RoomsWithClutter();
  SiteAlphaShape on_voronois(TriangulateIndexedSites(sites), 2.6);
  SiteAlphaShape on_its_own(sites, 2.6);
  ExpectSameShape(on_voronois, on_its_own);
}

TEST(SiteTriangulationTest, AKeptTriangulationIsGivenBackOnceForTheSameSites) {
  const PointList sites = RoomsWithClutter();
  KeepSiteTriangulation(TriangulateIndexedSites(sites), sites);
  SiteTriangulationPtr taken = TakeSiteTriangulation(sites);
  ASSERT_NE(taken, nullptr);
  EXPECT_GT(SiteTriangulationBytes(*taken), sites.size() * 16);
  EXPECT_EQ(TakeSiteTriangulation(sites), nullptr) << "given back twice";

  SiteAlphaShape on_kept(std::move(taken), 2.6);
  SiteAlphaShape on_its_own(sites, 2.6);
  ExpectSameShape(on_kept, on_its_own);
}

// What the old 64-MB bound dropped (lab_a tiled 8 x 8's is 170 MB) is kept
// now: prune would build the same triangulation itself.
TEST(SiteTriangulationTest, ATriangulationOfOver64MegabytesIsKept) {
  PointList sites;
  for (int row = 0; row < 640; ++row) {
    for (int col = 0; col < 640; ++col) sites.emplace_back(col + 0.25 * (row % 3), row);
  }
  SiteTriangulationPtr triangulation = TriangulateIndexedSites(sites);
  ASSERT_GT(SiteTriangulationBytes(*triangulation), size_t{64} << 20);
  KeepSiteTriangulation(std::move(triangulation), sites);
  EXPECT_NE(TakeSiteTriangulation(sites), nullptr);
}

TEST(SiteTriangulationTest, OtherSitesOrAnotherOrderGetNothingAndDropIt) {
  const PointList sites = RoomsWithClutter();
  PointList reordered = sites;
  std::swap(reordered[3], reordered[4]);
  KeepSiteTriangulation(TriangulateIndexedSites(sites), sites);
  EXPECT_EQ(TakeSiteTriangulation(reordered), nullptr);
  EXPECT_EQ(TakeSiteTriangulation(sites), nullptr) << "a miss keeps nothing";

  PointList fewer = sites;
  fewer.pop_back();
  KeepSiteTriangulation(TriangulateIndexedSites(sites), sites);
  EXPECT_EQ(TakeSiteTriangulation(fewer), nullptr);

  KeepSiteTriangulation(TriangulateIndexedSites(sites), sites);
  DropSiteTriangulation();
  EXPECT_EQ(TakeSiteTriangulation(sites), nullptr);
}

TEST(SiteTriangulationTest, ANewerTriangulationReplacesTheKeptOne) {
  const PointList sites = RoomsWithClutter();
  PointList other = sites;
  other.pop_back();
  KeepSiteTriangulation(TriangulateIndexedSites(sites), sites);
  KeepSiteTriangulation(TriangulateIndexedSites(other), other);
  EXPECT_EQ(TakeSiteTriangulation(sites), nullptr);
  KeepSiteTriangulation(TriangulateIndexedSites(other), other);
  EXPECT_NE(TakeSiteTriangulation(other), nullptr);
}

}  // namespace
}  // namespace areagraph

// SiteAlphaShape's outlines of several enclosed regions in one pass against
// one region at a time; the constructor that takes the sites over; rooms
// renumbered (twice, as ag-cut does) against a shape left as labelled.
#include "stages/geometry/site_alpha_shape.h"

#include <google/protobuf/util/message_differencer.h>
#include <gtest/gtest.h>

#include <set>

#include "stages/geometry/ring_points.h"

namespace areagraph {
namespace {

// The cells of a w x h rectangle's walls, from (x0, y0), one cell thick.
void AddBox(int x0, int y0, int w, int h, PointList* sites) {
  for (int x = x0; x < x0 + w; ++x) {
    sites->emplace_back(x + 0.5, y0 + 0.5);
    sites->emplace_back(x + 0.5, y0 + h - 0.5);
  }
  for (int y = y0 + 1; y < y0 + h - 1; ++y) {
    sites->emplace_back(x0 + 0.5, y + 0.5);
    sites->emplace_back(x0 + w - 0.5, y + 0.5);
  }
}

TEST(SiteAlphaShapeTest, OutlinesInOnePassEqualOneAtATime) {
  PointList sites;
  AddBox(0, 0, 20, 12, &sites);   // a room
  AddBox(30, 0, 10, 25, &sites);  // another, apart
  AddBox(3, 3, 4, 4, &sites);     // a pillar inside the first
  SiteAlphaShape shape(sites, 1.5);
  const std::vector<double> areas = shape.FindEnclosedRegions();
  ASSERT_GE(areas.size(), 2u);

  std::set<int> regions;
  for (int region = 0; region < static_cast<int>(areas.size()); ++region) regions.insert(region);
  regions.insert(static_cast<int>(areas.size()) +
                 5);  // unknown: an empty polygon, as one at a time
  const std::map<int, proto::Polygon> outlines = shape.EnclosedRegionOutlines(regions);
  ASSERT_EQ(outlines.size(), regions.size());
  int non_empty = 0;
  for (const int region : regions) {
    const proto::Polygon single = shape.EnclosedRegionOutline(region);
    EXPECT_TRUE(google::protobuf::util::MessageDifferencer::Equals(outlines.at(region), single))
        << "region " << region;
    non_empty += RingSize(single.outer()) >= 3 ? 1 : 0;
  }
  EXPECT_GE(non_empty, 2);
  EXPECT_TRUE(shape.EnclosedRegionOutlines({}).empty());
}

TEST(SiteAlphaShapeTest, TakingTheSitesOverFreesThemAndGivesTheSameShape) {
  PointList sites;
  AddBox(0, 0, 20, 12, &sites);
  AddBox(30, 0, 10, 25, &sites);
  SiteAlphaShape copied(sites, 1.5);
  PointList handed_over = sites;
  SiteAlphaShape taken(std::move(handed_over), 1.5);
  EXPECT_TRUE(handed_over.empty());
  EXPECT_EQ(handed_over.capacity(), 0u) << "the sites' memory was kept";
  const std::vector<double> areas = copied.FindEnclosedRegions();
  ASSERT_EQ(taken.FindEnclosedRegions(), areas);
  ASSERT_GE(areas.size(), 2u);
  for (int region = 0; region < static_cast<int>(areas.size()); ++region) {
    EXPECT_TRUE(google::protobuf::util::MessageDifferencer::Equals(
        taken.EnclosedRegionOutline(region), copied.EnclosedRegionOutline(region)))
        << "region " << region;
  }
}

TEST(SiteAlphaShapeTest, RenumberedRoomsKeepTheirFacesAreasAndOutlines) {
  PointList sites;
  AddBox(0, 0, 20, 12, &sites);
  AddBox(30, 0, 10, 25, &sites);
  AddBox(50, 0, 14, 14, &sites);
  AddBox(3, 3, 4, 4, &sites);
  // Faces whose centroid is right of x = 45 are no room.
  auto left_part = [](const Eigen::Vector2d& p) { return p.x() < 45; };
  SiteAlphaShape shape(sites, 1.5), as_labelled(sites, 1.5);
  const int count = shape.DetectRooms(left_part);
  ASSERT_EQ(as_labelled.DetectRooms(left_part), count);
  ASSERT_GE(count, 2);
  const std::vector<double> areas = shape.RoomAreas();
  ASSERT_EQ(areas.size(), static_cast<size_t>(count));
  std::vector<Eigen::Vector2d> probes;
  std::vector<int> labelled;
  for (double x = 0.3; x < 64; x += 0.7) {
    for (double y = 0.2; y < 25; y += 0.9) {
      probes.emplace_back(x, y);
      labelled.push_back(as_labelled.RoomAt(probes.back()));
    }
  }
  // Drop room 0 and reverse the others, then swap the first two kept.
  std::vector<int> first(count, -1), second(count - 1);
  for (int room = 1; room < count; ++room) first[room] = count - 1 - room;
  for (int id = 0; id < count - 1; ++id) second[id] = id < 2 && count > 2 ? 1 - id : id;
  shape.RenumberRooms(first);
  auto new_id = [&](int room) {
    return room < 0 ? -1 : first[room] < 0 ? -1 : second[first[room]];
  };
  const std::vector<double> after_first = shape.RoomAreas();
  for (int room = 1; room < count; ++room) EXPECT_EQ(after_first[first[room]], areas[room]);
  shape.RenumberRooms(second);
  for (size_t k = 0; k < probes.size(); ++k) {
    EXPECT_EQ(shape.RoomAt(probes[k]), new_id(labelled[k])) << probes[k].transpose();
  }
  const std::vector<proto::Polygon> outlines = shape.RoomOutlines();
  const std::vector<proto::Polygon> labelled_outlines = as_labelled.RoomOutlines();
  ASSERT_EQ(outlines.size(), static_cast<size_t>(count - 1));
  for (int room = 1; room < count; ++room) {
    EXPECT_TRUE(google::protobuf::util::MessageDifferencer::Equals(outlines[new_id(room)],
                                                                   labelled_outlines[room]))
        << "room " << room;
  }
  for (size_t k = 0; k < probes.size(); ++k) {
    EXPECT_EQ(shape.RoomAt(probes[k]), new_id(labelled[k])) << "after the outlines";
  }
}

// A renumbering may give ids past the rooms' count: they hold through the
// outlines, as when the faces carried the ids themselves.
TEST(SiteAlphaShapeTest, IdsPastTheRoomCountHoldThroughTheOutlines) {
  PointList sites;
  AddBox(0, 0, 20, 12, &sites);
  AddBox(30, 0, 10, 25, &sites);
  SiteAlphaShape shape(sites, 1.5);
  const int count = shape.DetectRooms([](const Eigen::Vector2d&) { return true; });
  ASSERT_GE(count, 2);
  const Eigen::Vector2d in_first(10, 6), in_second(35, 12);
  const int first = shape.RoomAt(in_first), second = shape.RoomAt(in_second);
  ASSERT_GE(first, 0);
  ASSERT_GE(second, 0);
  ASSERT_NE(first, second);
  std::vector<int> ids(count, -1);
  ids[first] = count + 6;
  ids[second] = count + 2;
  shape.RenumberRooms(ids);
  EXPECT_EQ(shape.RoomAt(in_first), count + 6);
  const std::vector<proto::Polygon> outlines = shape.RoomOutlines();
  ASSERT_EQ(outlines.size(), static_cast<size_t>(count + 7));
  EXPECT_GT(RingSize(outlines[count + 6].outer()), 0);
  EXPECT_GT(RingSize(outlines[count + 2].outer()), 0);
  EXPECT_EQ(shape.RoomAt(in_first), count + 6);
  EXPECT_EQ(shape.RoomAt(in_second), count + 2);
}

}  // namespace
}  // namespace areagraph

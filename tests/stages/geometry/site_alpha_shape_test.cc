// SiteAlphaShape's outlines of several enclosed regions in one pass against
// one region at a time; the constructor that takes the sites over.
#include "stages/geometry/site_alpha_shape.h"

#include <google/protobuf/util/message_differencer.h>
#include <gtest/gtest.h>

#include <set>

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
    non_empty += single.outer().points_size() >= 3 ? 1 : 0;
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

}  // namespace
}  // namespace areagraph

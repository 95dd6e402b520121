// The shortcuts that keep merge linear on big maps, against the ways they
// replace: MergeGroups against MergeInto area by area.
#include <gtest/gtest.h>

#include <opencv2/imgproc.hpp>
#include <random>

#include "stages/geometry/distance_transform.h"
#include "stages/merge/area_assignment.h"
#include "tests/support/area_test_support.h"

namespace areagraph::testing {
namespace {

// MergeGroups as it was: MergeInto from the last area down.
void MergeGroupsAreaByArea(std::vector<int> group, AreaPlan* plan) {
  for (int k = static_cast<int>(group.size()) - 1; k >= 0; --k) {
    const auto first = std::find(group.begin(), group.begin() + k, group[k]);
    if (first == group.begin() + k) continue;
    plan->MergeInto(k, static_cast<int>(first - group.begin()));
    group.erase(group.begin() + k);
  }
}

TEST(MergeGroupsTest, SameAsMergingAreaByArea) {
  std::mt19937 random(3);
  int merged = 0;
  for (int trial = 0; trial < 300; ++trial) {
    const int areas = std::uniform_int_distribution<int>(1, 40)(random);
    const int edges = std::uniform_int_distribution<int>(areas, 3 * areas + 5)(random);
    AreaPlan plan;
    plan.areas.resize(areas);
    plan.area_of_edge.assign(edges, -1);
    for (int k = 0; k < areas; ++k) {
      plan.areas[k].kind = static_cast<proto::AreaKind>(random() % 3);
      plan.areas[k].room_id = static_cast<int>(random() % 5) - 1;
    }
    // Most edges in one area each, in no order; a few in none.
    for (int e = 0; e < edges; ++e) {
      if (random() % 10 == 0) continue;
      const int k = std::uniform_int_distribution<int>(0, areas - 1)(random);
      plan.areas[k].edges.insert(
          plan.areas[k].edges.begin() + random() % (plan.areas[k].edges.size() + 1), e);
      plan.area_of_edge[e] = k;
    }
    // Group values of any size, few groups or many.
    const int values = std::uniform_int_distribution<int>(1, areas)(random);
    std::vector<int> group(areas);
    for (int& g : group) g = 1000 - 7 * std::uniform_int_distribution<int>(0, values - 1)(random);
    AreaPlan expected = plan;
    MergeGroupsAreaByArea(group, &expected);
    plan.MergeGroups(group);
    merged += areas - static_cast<int>(expected.areas.size());
    ASSERT_EQ(plan.areas.size(), expected.areas.size()) << trial;
    EXPECT_EQ(plan.area_of_edge, expected.area_of_edge) << trial;
    for (size_t k = 0; k < plan.areas.size(); ++k) {
      EXPECT_EQ(plan.areas[k].edges, expected.areas[k].edges) << trial << " " << k;
      EXPECT_EQ(plan.areas[k].kind, expected.areas[k].kind) << trial << " " << k;
      EXPECT_EQ(plan.areas[k].room_id, expected.areas[k].room_id) << trial << " " << k;
    }
  }
  EXPECT_GT(merged, 1000);
}

}  // namespace
}  // namespace areagraph::testing

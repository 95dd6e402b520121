// The shortcuts that keep merge linear on big maps, against the ways they
// replace: MergeGroups against MergeInto area by area, the corridor shapes
// of wide rooms against AreaShapes, DeepestDistanceLowerBound against
// DeepestDistance.
#include <gtest/gtest.h>

#include <opencv2/imgproc.hpp>
#include <random>

#include "stages/geometry/distance_transform.h"
#include "stages/merge/area_assignment.h"
#include "stages/merge/corridor_labels.h"
#include "stages/merge/deepest_bound.h"
#include "stages/merge/region_depth.h"
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

// A mask of random blobs and bands.
cv::Mat RandomMask(int rows, int cols, std::mt19937& random) {
  cv::Mat mask = cv::Mat::zeros(rows, cols, CV_8U);
  const int bands = std::uniform_int_distribution<int>(1, 4)(random);
  for (int k = 0; k < bands; ++k) {
    const int y = std::uniform_int_distribution<int>(1, rows - 2)(random);
    const int height = std::uniform_int_distribution<int>(1, std::max(1, (rows - y - 1)))(random);
    mask(cv::Rect(1, y, cols - 2, std::min(height, rows - 1 - y))).setTo(255);
  }
  for (int k = 0; k < 30; ++k) {
    const cv::Point centre(std::uniform_int_distribution<int>(0, cols - 1)(random),
                           std::uniform_int_distribution<int>(0, rows - 1)(random));
    const int radius = std::uniform_int_distribution<int>(1, 120)(random);
    cv::circle(mask, centre, radius, cv::Scalar(k % 3 == 0 ? 0 : 255), cv::FILLED);
  }
  // Zero all round, as LabelMaskInBox makes them.
  cv::rectangle(mask, cv::Rect(0, 0, cols, rows), cv::Scalar(0));
  return mask;
}

TEST(DeepestDistanceLowerBoundTest, AtMostDeepestDistanceAndItselfWhereExact) {
  std::mt19937 random(5);
  int close = 0;
  const std::vector<cv::Size> sizes{{4200, 150}, {150, 4300}, {4500, 700}, {300, 200}, {2100, 90}};
  for (int trial = 0; trial < 20; ++trial) {
    const cv::Size size = sizes[trial % sizes.size()];
    const cv::Mat mask = RandomMask(size.height, size.width, random);
    const double bound = DeepestDistanceLowerBound(mask);
    const double deepest = DeepestDistance(mask);
    if (ComputedExactly(size)) {
      EXPECT_EQ(bound, deepest) << trial;
    } else {
      EXPECT_LE(bound, deepest) << trial;
    }
    close += bound >= deepest - 1;
  }
  // The windows overlap: the deepest disk lies in one of them.
  EXPECT_EQ(close, 20);
}

// Every 8-connected region of `mask` that touches no border, as merge's
// island candidates, cells in row-major order.
std::vector<CellRegion> RegionsOf(const cv::Mat& mask) {
  cv::Mat labels, stats, centroids;
  const int count = cv::connectedComponentsWithStats(mask, labels, stats, centroids, 8, CV_32S);
  std::vector<CellRegion> regions(count - 1);
  for (int k = 1; k < count; ++k) {
    regions[k - 1].box =
        cv::Rect(stats.at<int>(k, cv::CC_STAT_LEFT), stats.at<int>(k, cv::CC_STAT_TOP),
                 stats.at<int>(k, cv::CC_STAT_WIDTH), stats.at<int>(k, cv::CC_STAT_HEIGHT));
  }
  for (int r = 0; r < mask.rows; ++r) {
    for (int c = 0; c < mask.cols; ++c) {
      const int k = labels.at<int>(r, c);
      if (k > 0) regions[k - 1].cells.emplace_back(c, r);
    }
  }
  const cv::Rect inner(1, 1, mask.cols - 2, mask.rows - 2);
  regions.erase(
      std::remove_if(regions.begin(), regions.end(),
                     [&](const CellRegion& region) { return (region.box & inner) != region.box; }),
      regions.end());
  return regions;
}

// Islands on masks wider than 4096 cells and on a small one: a region's
// thickness test comes out as DeepestPerRun's (the whole rows, as before)
// gives it, and a region that fails it gets DeepestPerRun's very value.
TEST(DeepestOfRegionsTest, ThickWhereDeepestPerRunSaysSo) {
  std::mt19937 random(11);
  int thick = 0, thin = 0;
  for (const cv::Size size : {cv::Size(4300, 160), cv::Size(4200, 4200), cv::Size(600, 300)}) {
    cv::Mat mask = cv::Mat::zeros(size, CV_8U);
    for (int k = 0; k < 400; ++k) {
      const cv::Point centre(std::uniform_int_distribution<int>(2, size.width - 3)(random),
                             std::uniform_int_distribution<int>(2, size.height - 3)(random));
      const int radius = std::uniform_int_distribution<int>(0, 12)(random);
      if (k % 2 == 0) {
        cv::circle(mask, centre, radius, cv::Scalar(255), cv::FILLED);
      } else {
        cv::rectangle(mask, cv::Rect(centre, cv::Size(radius + 1, 2 * radius + 1)), cv::Scalar(255),
                      cv::FILLED);
      }
    }
    const std::vector<CellRegion> regions = RegionsOf(mask);
    std::vector<PieceRun> runs;
    for (size_t k = 0; k < regions.size(); ++k) {
      for (const cv::Point& p : regions[k].cells) runs.push_back({p.y, p.x, p.x + 1, int(k) + 1});
    }
    const std::vector<float> before = DeepestPerRun(mask, runs, int(regions.size()) + 1);
    for (const double min_thickness_px : {3.0, 9.5, 16.0}) {
      const std::vector<float> deepest = DeepestOfRegions(mask, regions, min_thickness_px);
      ASSERT_EQ(deepest.size(), regions.size());
      for (size_t k = 0; k < regions.size(); ++k) {
        const bool reaches = 2 * deepest[k] >= min_thickness_px;
        ASSERT_EQ(reaches, 2 * before[k + 1] >= min_thickness_px) << size << " " << k;
        if (!reaches) EXPECT_EQ(deepest[k], before[k + 1]) << size << " " << k;
        thick += reaches, thin += !reaches;
      }
    }
  }
  EXPECT_GT(thick, 100);
  EXPECT_GT(thin, 100);
}

// Rooms on a raster wider than 4096 cells: bands that run its width, halls
// and corridors, so that the lower bound decides some and not others.
TEST(CorridorLabelsTest, WideRoomsGetTheKindsOfTheirShapes) {
  std::mt19937 random(8);
  for (int trial = 0; trial < 3; ++trial) {
    AreaRaster raster;
    raster.labels = cv::Mat::zeros(600, 4400, CV_32S);
    int y = 2, label = 0;
    while (y < 560) {
      const int height = std::uniform_int_distribution<int>(20, 120)(random);
      const int width = std::uniform_int_distribution<int>(3000, 4390)(random);
      raster.labels(cv::Rect(3, y, width, std::min(height, 597 - y))).setTo(++label);
      // A pillar: a hole that filling gives back.
      raster.labels(cv::Rect(100, y + height / 3, 10, 5)).setTo(0);
      y += height + 3;
    }
    raster.cell_count.resize(label);
    CountAreaCells(&raster);
    AreaPlan plan;
    for (int k = 0; k < label; ++k) plan.areas.push_back({proto::AREA_ROOM, k, {k}});
    const std::vector<AreaShape> shapes = AreaShapes(raster);
    LabelCorridorsByShape(raster, 0.05, &plan);
    int corridors = 0;
    for (int k = 0; k < label; ++k) {
      const bool corridor = IsCorridorShaped(shapes[k], 0.05);
      EXPECT_EQ(plan.areas[k].kind, corridor ? proto::AREA_CORRIDOR : proto::AREA_ROOM)
          << trial << " " << k;
      corridors += corridor;
    }
    EXPECT_GT(corridors, 0) << trial;
    EXPECT_LT(corridors, label) << trial;
  }
}

}  // namespace
}  // namespace areagraph::testing

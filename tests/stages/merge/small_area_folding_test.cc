// FoldSmallAreas' one relabelling pass (run by run, writing only the runs
// whose label changes): on random rasters of rectangles, every old label
// maps to one new label, the areas' cells and boxes it keeps match the
// relabelled raster, and cells of no area stay as they were.
#include "stages/merge/small_area_folding.h"

#include <gtest/gtest.h>

#include <map>
#include <random>

namespace areagraph::testing {
namespace {

TEST(SmallAreaFolding, RelabelledRasterMatchesTheAreas) {
  std::mt19937 random(16);
  auto uniform = [&](int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(random); };
  int folds = 0;
  for (int trial = 0; trial < 100; ++trial) {
    const int count = uniform(2, 25);
    AreaRaster raster;
    raster.labels = cv::Mat(uniform(10, 60), uniform(10, 90), CV_32S, cv::Scalar(0));
    for (int k = 0; k < count; ++k) {
      const cv::Rect rect(uniform(-5, raster.labels.cols), uniform(-5, raster.labels.rows),
                          uniform(1, 30), uniform(1, 20));
      raster.labels(rect & cv::Rect(0, 0, raster.labels.cols, raster.labels.rows)).setTo(k + 1);
    }
    // Some cells of no area (0) and of free space never reached (-1).
    for (int k = 0; k < 20; ++k) {
      raster.labels.at<int>(uniform(0, raster.labels.rows - 1),
                            uniform(0, raster.labels.cols - 1)) = uniform(-1, 0);
    }
    const cv::Mat before = raster.labels.clone();
    raster.cell_count.assign(count, 0);
    CountAreaCells(&raster);
    AreaPlan plan;
    plan.areas.resize(count);
    proto::CutGraph graph;
    FoldSmallAreas(graph, uniform(5, 200), &plan, &raster);
    folds += count - static_cast<int>(plan.areas.size());
    ASSERT_EQ(raster.cell_count.size(), plan.areas.size());
    std::map<int, int> new_of_old;
    for (int r = 0; r < before.rows; ++r) {
      for (int c = 0; c < before.cols; ++c) {
        const int old_label = before.at<int>(r, c), now = raster.labels.at<int>(r, c);
        if (old_label <= 0) {
          ASSERT_EQ(now, old_label);
          continue;
        }
        ASSERT_GE(now, 1);
        ASSERT_LE(now, static_cast<int>(plan.areas.size()));
        const auto [it, inserted] = new_of_old.emplace(old_label, now);
        ASSERT_EQ(it->second, now) << "label " << old_label << " split";
      }
    }
    AreaRaster recount;
    recount.labels = raster.labels;
    recount.cell_count.assign(plan.areas.size(), 0);
    CountAreaCells(&recount);
    EXPECT_EQ(recount.cell_count, raster.cell_count);
    EXPECT_EQ(recount.boxes, raster.boxes);
  }
  EXPECT_GT(folds, 100);
}

}  // namespace
}  // namespace areagraph::testing

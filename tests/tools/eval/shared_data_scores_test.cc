// Scores of the shipped segmentations in ../shared/data, against the figures
// in the datasets' READMEs. Skipped when the data is absent.
#include <gtest/gtest.h>

#include "tests/support/test_support.h"
#include "tools/eval/dataset_evaluation.h"

namespace areagraph {
namespace {

using testing::HaveSharedData;
using testing::SharedDataPath;

double MeanMcc(const DatasetEvaluation& dataset) {
  std::vector<double> mcc;
  for (const MapEvaluation& map : dataset.maps) mcc.push_back(map.mcc);
  return Mean(mcc);
}

DatasetLayout MaorisLayout() {
  return {SharedDataPath("maoris/RobotMap/maoris/t03m01R40D50"),
          SharedDataPath("maoris/RobotMap/GT"), "", ""};
}

// maoris/README.md: a re-implementation of MAORIS' compareImagesUnbiased and
// segment_Ground_Truth gives mean 0.891 (median 0.980) over the 20 maps with
// a GT (X_straighten.png files have none). MAORIS' own TN, its matching and
// its GT reading reproduce that.
TEST(SharedDataScores, MaorisResultsWithMaorisCodeMatchTheReadme) {
  if (!HaveSharedData()) GTEST_SKIP() << "no ../shared/data";
  EvaluationOptions options;
  options.gt_style = GroundTruthStyle::kMaorisLines;
  options.mcc_variant = MccVariant::kMaoris;
  const DatasetEvaluation dataset = EvaluateDataset(MaorisLayout(), options);
  EXPECT_TRUE(dataset.failures.empty());
  ASSERT_EQ(dataset.maps.size(), 20u);
  EXPECT_NEAR(MeanMcc(dataset), 0.891, 0.01);
}

// With the standard TN = N - TP - FP - FN and each GT zone matched at most
// once the same files give 0.881 (MAORIS' GT reading) ...
TEST(SharedDataScores, MaorisResultsWithStandardMcc) {
  if (!HaveSharedData()) GTEST_SKIP() << "no ../shared/data";
  EvaluationOptions options;
  options.gt_style = GroundTruthStyle::kMaorisLines;
  const DatasetEvaluation dataset = EvaluateDataset(MaorisLayout(), options);
  ASSERT_EQ(dataset.maps.size(), 20u);
  EXPECT_NEAR(MeanMcc(dataset), 0.881, 0.01);
}

// ... and 0.831 with the default (auto = Bormann's line reading), where the
// MAORIS authors' edited Freiburg101_scan GT leaks into a single 8-connected
// room and scores 0.
TEST(SharedDataScores, MaorisResultsWithDefaults) {
  if (!HaveSharedData()) GTEST_SKIP() << "no ../shared/data";
  const DatasetEvaluation dataset = EvaluateDataset(MaorisLayout(), EvaluationOptions());
  ASSERT_EQ(dataset.maps.size(), 20u);
  EXPECT_NEAR(MeanMcc(dataset), 0.831, 0.01);
}

// areagraph/README.md, "regions > 100 px" column: strategy_w 0.658 with
// MAORIS' per-zone MCC; freiburg_building101's padded GT sits at x = 192.
TEST(SharedDataScores, AreaGraphStrategyWMatchesTheReadme) {
  if (!HaveSharedData()) GTEST_SKIP() << "no ../shared/data";
  EvaluationOptions options;
  options.mcc_variant = MccVariant::kMaoris;
  options.drop_result_segments_px = 100;
  const DatasetEvaluation dataset = EvaluateDataset(
      {SharedDataPath("areagraph/strategy_w"), SharedDataPath("areagraph/GT"), "", ""}, options);
  EXPECT_TRUE(dataset.failures.empty());
  ASSERT_EQ(dataset.maps.size(), 16u);
  EXPECT_NEAR(MeanMcc(dataset), 0.658, 0.01);
  for (const MapEvaluation& map : dataset.maps) {
    if (map.name == "freiburg_building101") {
      EXPECT_EQ(map.gt_offset, cv::Point(192, 0));
    }
  }
}

}  // namespace
}  // namespace areagraph

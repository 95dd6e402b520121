// Scores of small label images whose expected values are worked out by hand.
#include "tools/eval/per_zone_mcc.h"

#include <gtest/gtest.h>

#include <cmath>
#include <opencv2/core.hpp>

#include "tools/eval/map_evaluation.h"
#include "tools/eval/zone_overlaps.h"

namespace areagraph {
namespace {

// A 10x40 label image: `first` in columns [0, split), `second` after.
cv::Mat TwoColumns(int split, int first = 1, int second = 2) {
  cv::Mat labels(10, 40, CV_32S, cv::Scalar(second));
  labels.colRange(0, split).setTo(first);
  return labels;
}

TEST(PerZoneMcc, IdenticalSegmentationsScoreOne) {
  cv::Mat gt(30, 40, CV_32S, cv::Scalar(0));
  gt(cv::Rect(0, 0, 20, 15)).setTo(3);
  gt(cv::Rect(20, 0, 20, 15)).setTo(7);
  gt(cv::Rect(0, 15, 40, 15)).setTo(9);
  // Different label values, same partition.
  cv::Mat result = gt * 2;
  const MapEvaluation scores = ScoreLabelImages(result, gt, MccVariant::kStandard);
  EXPECT_DOUBLE_EQ(scores.mcc, 1.0);
  EXPECT_DOUBLE_EQ(scores.precision, 1.0);
  EXPECT_DOUBLE_EQ(scores.recall, 1.0);
  EXPECT_EQ(scores.result_segments, 3);
  EXPECT_EQ(scores.gt_segments, 3);
  EXPECT_EQ(scores.scored_pixels, 30 * 40);
}

TEST(PerZoneMcc, OneZoneEachIsAPerfectMatch) {
  const cv::Mat everything(10, 40, CV_32S, cv::Scalar(1));
  EXPECT_DOUBLE_EQ(ScoreLabelImages(everything, everything, MccVariant::kStandard).mcc, 1.0);
}

// GT: halves of 200 px (columns 0-19 and 20-39). Result: 250 px + 150 px
// (split at column 25). N = 400.
// Result zone 1 (largest overlap 200) -> GT 1: TP 200, FP 50, FN 0, TN 150,
//   MCC = 200*150 / sqrt(250*200*200*150) = sqrt(0.6).
// Result zone 2 -> GT 2: TP 150, FP 0, FN 50, TN 200, MCC = sqrt(0.6) too.
// Precision = (200/250 + 150/150) / 2 = 0.9; recall = (200/200 + 150/200) / 2.
TEST(PerZoneMcc, HandComputedSplit) {
  const MapEvaluation scores =
      ScoreLabelImages(TwoColumns(25), TwoColumns(20), MccVariant::kStandard);
  EXPECT_NEAR(scores.mcc, std::sqrt(0.6), 1e-12);
  EXPECT_NEAR(scores.precision, 0.9, 1e-12);
  EXPECT_NEAR(scores.recall, 0.875, 1e-12);
}

TEST(PerZoneMcc, HandComputedConfusionCounts) {
  const PerZoneMcc mcc =
      ComputePerZoneMcc(CountZoneOverlaps(TwoColumns(25), TwoColumns(20)), MccVariant::kStandard);
  ASSERT_EQ(mcc.matches.size(), 2u);
  const ZoneMatch& first = mcc.matches[0];
  EXPECT_EQ(first.result, 1);
  EXPECT_EQ(first.gt, 1);
  EXPECT_EQ(first.tp, 200);
  EXPECT_EQ(first.fp, 50);
  EXPECT_EQ(first.fn, 0);
  EXPECT_EQ(first.tn, 150);
  const ZoneMatch& second = mcc.matches[1];
  EXPECT_EQ(second.tp, 150);
  EXPECT_EQ(second.fp, 0);
  EXPECT_EQ(second.fn, 50);
  EXPECT_EQ(second.tn, 200);
}

// MAORIS' TN = N - (FP - |GT zone|): zone 1 gets 400 - (50 - 200) = 550,
// MCC = 200*550 / sqrt(250*200*600*550); zone 2 gets 400 - (0 - 200) = 600,
// MCC = 150*600 / sqrt(150*200*600*650).
TEST(PerZoneMcc, MaorisVariantUsesItsTrueNegatives) {
  const double first = 200.0 * 550 / std::sqrt(250.0 * 200 * 600 * 550);
  const double second = 150.0 * 600 / std::sqrt(150.0 * 200 * 600 * 650);
  const MapEvaluation scores =
      ScoreLabelImages(TwoColumns(25), TwoColumns(20), MccVariant::kMaoris);
  EXPECT_NEAR(scores.mcc, (first + second) / 2, 1e-12);
}

// One result zone over two GT halves: it matches GT 1 (the tie goes to the
// smaller label) with TP 200, FP 200, FN 0, TN 0 -> 0/0 with FP > 0 -> 0; GT 2
// stays unmatched and adds another 0.
TEST(PerZoneMcc, UnderSegmentationScoresZero) {
  const cv::Mat one(10, 40, CV_32S, cv::Scalar(5));
  const PerZoneMcc mcc =
      ComputePerZoneMcc(CountZoneOverlaps(one, TwoColumns(20)), MccVariant::kStandard);
  ASSERT_EQ(mcc.matches.size(), 1u);
  EXPECT_EQ(mcc.matches[0].gt, 1);
  EXPECT_EQ(mcc.unmatched_gt_zones, 1);
  EXPECT_DOUBLE_EQ(mcc.mean, 0.0);
}

// Three result columns over one GT zone: the first match is perfect in
// precision, the other two result zones find no free GT zone and score 0
// (standard); MAORIS' code matches them to the taken GT zone anyway.
TEST(PerZoneMcc, OverSegmentationLeavesResultZonesUnmatched) {
  cv::Mat result(10, 30, CV_32S, cv::Scalar(1));
  result.colRange(10, 20).setTo(2);
  result.colRange(20, 30).setTo(3);
  const cv::Mat gt(10, 30, CV_32S, cv::Scalar(1));
  const ZoneOverlaps counts = CountZoneOverlaps(result, gt);
  const PerZoneMcc standard = ComputePerZoneMcc(counts, MccVariant::kStandard);
  EXPECT_EQ(standard.matches.size(), 1u);
  EXPECT_EQ(standard.unmatched_result_zones, 2);
  const PerZoneMcc maoris = ComputePerZoneMcc(counts, MccVariant::kMaoris);
  EXPECT_EQ(maoris.matches.size(), 3u);
  EXPECT_EQ(maoris.unmatched_result_zones, 0);
}

TEST(PerZoneMcc, BackgroundInEitherImageIsNotScored) {
  cv::Mat result = TwoColumns(20);
  cv::Mat gt = TwoColumns(20);
  result.row(0).setTo(0);
  gt.row(9).setTo(0);
  // A result zone that lies only on GT background does not count.
  result(cv::Rect(0, 9, 5, 1)).setTo(4);
  const MapEvaluation scores = ScoreLabelImages(result, gt, MccVariant::kStandard);
  EXPECT_EQ(scores.scored_pixels, 8 * 40);
  EXPECT_DOUBLE_EQ(scores.mcc, 1.0);
}

TEST(PerZoneMcc, EmptySegmentationScoresZero) {
  const cv::Mat empty(10, 40, CV_32S, cv::Scalar(0));
  const MapEvaluation scores = ScoreLabelImages(empty, TwoColumns(20), MccVariant::kStandard);
  EXPECT_DOUBLE_EQ(scores.mcc, 0.0);
  EXPECT_DOUBLE_EQ(scores.precision, 0.0);
  EXPECT_DOUBLE_EQ(scores.recall, 0.0);
}

TEST(MatthewsCorrelation, KnownValues) {
  EXPECT_DOUBLE_EQ(MatthewsCorrelation(10, 0, 0, 10), 1.0);
  EXPECT_DOUBLE_EQ(MatthewsCorrelation(0, 10, 10, 0), -1.0);
  EXPECT_NEAR(MatthewsCorrelation(6, 2, 1, 3), (18.0 - 2.0) / std::sqrt(8.0 * 7 * 5 * 4), 1e-12);
  EXPECT_DOUBLE_EQ(MatthewsCorrelation(5, 0, 0, 0), 1.0);
  EXPECT_DOUBLE_EQ(MatthewsCorrelation(5, 5, 0, 0), 0.0);
}

}  // namespace
}  // namespace areagraph

// Kinds of zones: the kinds file and the kind accuracy.
#include "tools/eval/zone_kinds.h"

#include <gtest/gtest.h>

#include <opencv2/imgcodecs.hpp>

#include "common/error.h"
#include "tests/support/test_support.h"
#include "tools/eval/map_evaluation.h"

namespace areagraph {
namespace {

using testing::TempDir;
using testing::WriteFile;

TEST(ZoneKindsTest, KindsFileIsBesideTheImage) {
  EXPECT_EQ(KindsPathFor("out/maps/floor_1.png"), "out/maps/floor_1.kinds.tsv");
}

TEST(ZoneKindsTest, ReadsLabelsAndKinds) {
  TempDir dir;
  WriteFile(dir.File("a.kinds.tsv"), "label\tkind\n1\troom\n2\tcorridor\n5\tdead_end\n");
  const ZoneKinds kinds = ReadZoneKinds(dir.File("a.kinds.tsv"));
  EXPECT_EQ(kinds, (ZoneKinds{{1, "room"}, {2, "corridor"}, {5, "dead_end"}}));
}

TEST(ZoneKindsTest, RefusesBadFiles) {
  TempDir dir;
  WriteFile(dir.File("no_header.tsv"), "1\troom\n");
  WriteFile(dir.File("bad_kind.tsv"), "label\tkind\n1\tkitchen\n");
  WriteFile(dir.File("bad_label.tsv"), "label\tkind\n0\troom\n");
  WriteFile(dir.File("extra.tsv"), "label\tkind\n1\troom corridor\n");
  for (const char* name : {"no_header.tsv", "bad_kind.tsv", "bad_label.tsv", "extra.tsv"}) {
    EXPECT_THROW(ReadZoneKinds(dir.File(name)), InputError) << name;
  }
  EXPECT_THROW(ReadZoneKinds(dir.File("missing.tsv")), InputError);
}

// A GT of a room (1) beside a corridor (2); the result finds the room (10),
// the corridor in two pieces (20, 30) and calls one piece a room.
struct Scene {
  cv::Mat gt = cv::Mat::zeros(10, 20, CV_32S);
  cv::Mat result = cv::Mat::zeros(10, 20, CV_32S);
  Scene() {
    gt(cv::Rect(0, 0, 10, 10)).setTo(1);
    gt(cv::Rect(10, 0, 10, 10)).setTo(2);
    result(cv::Rect(0, 0, 11, 10)).setTo(10);  // one column into the corridor
    result(cv::Rect(11, 0, 5, 10)).setTo(20);
    result(cv::Rect(16, 0, 4, 10)).setTo(30);
  }
};

TEST(ZoneKindsTest, AccuracyIsTheRightShareOfTheResultsArea) {
  const Scene scene;
  const ZoneOverlaps counts = CountZoneOverlaps(scene.result, scene.gt);
  const ZoneKinds gt{{1, "room"}, {2, "corridor"}};
  // Zone 10 (110 px) overlaps the room most and is a room; 20 (50 px) is a
  // corridor; 30 (40 px) is called a room.
  const auto accuracy = KindAccuracy(counts, {{10, "room"}, {20, "corridor"}, {30, "room"}}, gt);
  ASSERT_TRUE(accuracy.has_value());
  EXPECT_DOUBLE_EQ(*accuracy, 160.0 / 200.0);
  // A dead end inside a GT corridor is right; a corridor in a GT room is not.
  EXPECT_DOUBLE_EQ(*KindAccuracy(counts, {{10, "room"}, {20, "corridor"}, {30, "dead_end"}}, gt),
                   1.0);
  EXPECT_DOUBLE_EQ(
      *KindAccuracy(counts, {{10, "corridor"}, {20, "corridor"}, {30, "corridor"}}, gt),
      90.0 / 200.0);
  // Zones without a kind do not count; nothing that counts gives no score.
  EXPECT_DOUBLE_EQ(*KindAccuracy(counts, {{20, "corridor"}}, gt), 1.0);
  EXPECT_FALSE(KindAccuracy(counts, {}, gt).has_value());
}

TEST(ZoneKindsTest, EvaluateMapScoresKindsOnlyWithBothFiles) {
  const Scene scene;
  TempDir dir;
  cv::Mat result16, gt16;
  scene.result.convertTo(result16, CV_16U);
  scene.gt.convertTo(gt16, CV_16U);
  ASSERT_TRUE(cv::imwrite(dir.File("r.png"), result16));
  ASSERT_TRUE(cv::imwrite(dir.File("g.png"), gt16));
  EvaluationOptions options;
  options.gt_style = GroundTruthStyle::kLabels;
  EXPECT_FALSE(EvaluateMap(dir.File("r.png"), dir.File("g.png"), options).kind_accuracy);
  WriteFile(dir.File("g.kinds.tsv"), "label\tkind\n1\troom\n2\tcorridor\n");
  EXPECT_FALSE(EvaluateMap(dir.File("r.png"), dir.File("g.png"), options).kind_accuracy);
  WriteFile(dir.File("r.kinds.tsv"), "label\tkind\n10\troom\n20\tcorridor\n30\troom\n");
  const MapEvaluation scored = EvaluateMap(dir.File("r.png"), dir.File("g.png"), options);
  ASSERT_TRUE(scored.kind_accuracy.has_value());
  EXPECT_DOUBLE_EQ(*scored.kind_accuracy, 0.8);
}

}  // namespace
}  // namespace areagraph

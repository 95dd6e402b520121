// Ground-truth styles: detection, labelling and alignment of padded GTs.
#include "tools/eval/ground_truth.h"

#include <gtest/gtest.h>

#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

#include "common/error.h"
#include "tools/eval/ground_truth_alignment.h"
#include "tools/eval/label_image.h"

namespace areagraph {
namespace {

// A Bormann-style GT: white rooms (left and right) split by a one-pixel grey
// line, inside black walls.
cv::Mat LineStyleGt() {
  cv::Mat grey(40, 60, CV_8U, cv::Scalar(0));
  grey(cv::Rect(2, 2, 56, 36)).setTo(255);
  grey.col(30).rowRange(2, 38).setTo(120);
  return grey;
}

// A colour GT: two coloured rooms, black walls, a grey unknown strip, white
// outside and a few anti-aliasing pixels of a third colour.
cv::Mat ColourGt() {
  cv::Mat bgr(40, 60, CV_8UC3, cv::Scalar(255, 255, 255));
  bgr(cv::Rect(0, 0, 30, 30)).setTo(cv::Scalar(0, 0, 200));
  bgr(cv::Rect(30, 0, 30, 30)).setTo(cv::Scalar(0, 180, 0));
  bgr.row(30).setTo(cv::Scalar(0, 0, 0));
  bgr(cv::Rect(0, 31, 60, 3)).setTo(cv::Scalar(153, 153, 153));
  bgr(cv::Rect(0, 35, 5, 5)).setTo(cv::Scalar(10, 90, 200));
  return bgr;
}

TEST(GroundTruthStyle, DetectsColourLinesAndLabels) {
  EXPECT_EQ(DetectGroundTruthStyle(ColourGt()), GroundTruthStyle::kColour);
  EXPECT_EQ(DetectGroundTruthStyle(LineStyleGt()), GroundTruthStyle::kLines);
  cv::Mat line_style_rgb;
  cv::cvtColor(LineStyleGt(), line_style_rgb, cv::COLOR_GRAY2BGR);
  EXPECT_EQ(DetectGroundTruthStyle(line_style_rgb), GroundTruthStyle::kLines);
  cv::Mat labels(40, 60, CV_8U, cv::Scalar(1));
  labels.colRange(30, 60).setTo(2);
  EXPECT_EQ(DetectGroundTruthStyle(labels), GroundTruthStyle::kLabels);
  cv::Mat labels16(40, 60, CV_16U, cv::Scalar(40000));
  EXPECT_EQ(DetectGroundTruthStyle(labels16), GroundTruthStyle::kLabels);
}

TEST(GroundTruthStyle, ParsesNamesAndRejectsUnknownOnes) {
  EXPECT_EQ(ParseGroundTruthStyle("colour"), GroundTruthStyle::kColour);
  EXPECT_EQ(ParseGroundTruthStyle("color"), GroundTruthStyle::kColour);
  EXPECT_EQ(ParseGroundTruthStyle("maoris-lines"), GroundTruthStyle::kMaorisLines);
  EXPECT_THROW(ParseGroundTruthStyle("stripes"), OptionsError);
}

TEST(GroundTruthLabels, ColourStyleKeepsChromaticColoursAboveHundredPixels) {
  const cv::Mat bgr = ColourGt();
  const cv::Mat labels = GroundTruthLabels(bgr, cv::Mat(), GroundTruthStyle::kColour);
  EXPECT_EQ(CountSegments(labels), 2);  // the 25-px colour is dropped
  EXPECT_NE(labels.at<int>(5, 5), 0);
  EXPECT_NE(labels.at<int>(5, 45), 0);
  EXPECT_NE(labels.at<int>(5, 5), labels.at<int>(5, 45));
  EXPECT_EQ(labels.at<int>(30, 5), 0);   // black
  EXPECT_EQ(labels.at<int>(32, 5), 0);   // grey
  EXPECT_EQ(labels.at<int>(37, 2), 0);   // small colour
  EXPECT_EQ(labels.at<int>(39, 50), 0);  // white
}

TEST(GroundTruthLabels, LinesSplitRoomsAndDropSmallOnes) {
  cv::Mat grey = LineStyleGt();
  // A closet of 9x9 = 81 px: walled off, at most 100 px, so dropped.
  grey(cv::Rect(40, 20, 11, 1)).setTo(0);
  grey(cv::Rect(40, 20, 1, 11)).setTo(0);
  grey(cv::Rect(50, 20, 1, 11)).setTo(0);
  grey(cv::Rect(40, 30, 11, 1)).setTo(0);
  const cv::Mat labels = LabelsFromLines(grey);
  EXPECT_EQ(CountSegments(labels), 2);
  EXPECT_NE(labels.at<int>(10, 10), labels.at<int>(10, 50));
  EXPECT_EQ(labels.at<int>(25, 45), 0);
  EXPECT_EQ(labels.at<int>(10, 30), 0);  // the line itself
}

TEST(GroundTruthLabels, LinesUseEightConnectivity) {
  cv::Mat grey(40, 60, CV_8U, cv::Scalar(255));
  // A diagonal line of single pixels does not separate 8-connected rooms.
  for (int i = 0; i < 40; ++i) grey.at<uchar>(i, 10 + i) = 0;
  EXPECT_EQ(CountSegments(LabelsFromLines(grey)), 1);
  // A 4-connected staircase does.
  for (int i = 0; i + 1 < 40; ++i) grey.at<uchar>(i, 11 + i) = 0;
  EXPECT_EQ(CountSegments(LabelsFromLines(grey)), 2);
}

TEST(GroundTruthLabels, MaorisLinesGrowRoomsBackOverTheErosion) {
  const cv::Mat labels = LabelsFromLinesLikeMaoris(LineStyleGt());
  EXPECT_EQ(CountSegments(labels), 2);
  // Erosion then dilation: the room's corner pixel (2,2) is back.
  EXPECT_NE(labels.at<int>(2, 2), 0);
  EXPECT_EQ(labels.at<int>(1, 1), 0);
}

TEST(GroundTruthAlignment, FindsTheOffsetOfAPaddedGt) {
  cv::Mat result(50, 30, CV_32S, cv::Scalar(0));
  result(cv::Rect(5, 5, 10, 30)).setTo(1);
  result(cv::Rect(15, 5, 10, 40)).setTo(2);
  cv::Mat gt(50, 100, CV_32S, cv::Scalar(0));
  result.copyTo(gt(cv::Rect(42, 0, 30, 50)));
  const GroundTruthOffset found = FindGroundTruthOffset(gt, result);
  EXPECT_EQ(found.offset, cv::Point(42, 0));
  EXPECT_NEAR(found.agreement, 1.0, 1e-6);
  const cv::Mat cropped = CropGroundTruth(gt, result.size(), found.offset);
  EXPECT_EQ(cv::countNonZero(cropped != result), 0);
}

TEST(GroundTruthAlignment, RejectsSmallerOrUnrelatedGt) {
  const cv::Mat result(50, 30, CV_32S, cv::Scalar(1));
  EXPECT_THROW(FindGroundTruthOffset(cv::Mat(40, 30, CV_32S, cv::Scalar(1)), result), InputError);
  EXPECT_THROW(FindGroundTruthOffset(cv::Mat(50, 60, CV_32S, cv::Scalar(0)), result), InputError);
  EXPECT_THROW(CropGroundTruth(cv::Mat(50, 60, CV_32S), result.size(), {31, 0}), InputError);
}

}  // namespace
}  // namespace areagraph

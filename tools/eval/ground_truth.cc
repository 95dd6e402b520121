#include "tools/eval/ground_truth.h"

#include <opencv2/imgproc.hpp>
#include <vector>

#include "common/error.h"
#include "tools/eval/label_image.h"

namespace areagraph {

GroundTruthStyle ParseGroundTruthStyle(const std::string& name) {
  if (name == "auto") return GroundTruthStyle::kAuto;
  if (name == "colour" || name == "color") return GroundTruthStyle::kColour;
  if (name == "lines") return GroundTruthStyle::kLines;
  if (name == "maoris-lines") return GroundTruthStyle::kMaorisLines;
  if (name == "labels") return GroundTruthStyle::kLabels;
  throw OptionsError("unknown ground-truth style '" + name +
                     "'; use auto, colour, lines, maoris-lines or labels");
}

std::string GroundTruthStyleName(GroundTruthStyle style) {
  switch (style) {
    case GroundTruthStyle::kAuto:
      return "auto";
    case GroundTruthStyle::kColour:
      return "colour";
    case GroundTruthStyle::kLines:
      return "lines";
    case GroundTruthStyle::kMaorisLines:
      return "maoris-lines";
    case GroundTruthStyle::kLabels:
      return "labels";
  }
  return "unknown";
}

GroundTruthStyle DetectGroundTruthStyle(const cv::Mat& raw) {
  if (CountChromaticPixels(raw) > kSmallSegmentPixels) return GroundTruthStyle::kColour;
  if (raw.depth() == CV_16U) return GroundTruthStyle::kLabels;
  const cv::Mat grey = ToGrey8(raw);
  const int free_pixels = cv::countNonZero(grey > 250);
  if (free_pixels >= 0.05 * static_cast<double>(grey.total())) return GroundTruthStyle::kLines;
  return GroundTruthStyle::kLabels;
}

cv::Mat LabelsFromLines(const cv::Mat& grey) {
  cv::Mat labels;
  cv::connectedComponents(grey > 250, labels, 8, CV_32S);
  DropSmallSegments(&labels, kSmallSegmentPixels);
  return labels;
}

cv::Mat LabelsFromLinesLikeMaoris(const cv::Mat& grey) {
  cv::Mat free = grey > 250;
  cv::erode(free, free, cv::Mat(), cv::Point(-1, -1), 1, cv::BORDER_CONSTANT,
            cv::morphologyDefaultBorderValue());
  std::vector<std::vector<cv::Point>> contours;
  std::vector<cv::Vec4i> hierarchy;
  cv::findContours(free, contours, hierarchy, cv::RETR_CCOMP, cv::CHAIN_APPROX_SIMPLE);
  cv::Mat drawing(grey.size(), CV_8U, cv::Scalar(0));
  // Top-level contours are linked through hierarchy[i][0]; drawing one with
  // the hierarchy fills it and leaves its holes empty.
  int label = 1;
  for (int index = contours.empty() ? -1 : 0; index >= 0; index = hierarchy[index][0]) {
    cv::drawContours(drawing, contours, index, cv::Scalar(label), cv::FILLED, cv::LINE_8,
                     hierarchy);
    ++label;
  }
  cv::dilate(drawing, drawing, cv::Mat(), cv::Point(-1, -1), 1, cv::BORDER_CONSTANT,
             cv::morphologyDefaultBorderValue());
  cv::Mat labels;
  drawing.convertTo(labels, CV_32S);
  return labels;
}

cv::Mat GroundTruthLabels(const cv::Mat& raw, const cv::Mat& grey, GroundTruthStyle style) {
  switch (style) {
    case GroundTruthStyle::kColour: {
      cv::Mat labels = LabelsFromColours(raw);
      DropSmallSegments(&labels, kSmallSegmentPixels);
      return labels;
    }
    case GroundTruthStyle::kLines:
      return LabelsFromLines(grey);
    case GroundTruthStyle::kMaorisLines:
      return LabelsFromLinesLikeMaoris(grey);
    case GroundTruthStyle::kLabels:
      return LabelsFromGreyValues(raw);
    case GroundTruthStyle::kAuto:
      break;
  }
  throw OptionsError("ground-truth style must be resolved before labelling");
}

}  // namespace areagraph

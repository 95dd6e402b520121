#include "tools/eval/gt_picture.h"

#include <cmath>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "common/error.h"
#include "stages/common/png_file.h"
#include "tools/eval/label_image.h"
#include "tools/eval/map_evaluation.h"

namespace areagraph {
namespace {

// Well separated colours for ids: golden-angle hues (BGR).
cv::Vec3b SegmentColour(int id) {
  cv::Mat hsv(1, 1, CV_8UC3, cv::Scalar(std::fmod(id * 137.508, 360.0) / 2, 150, 235));
  cv::Mat bgr;
  cv::cvtColor(hsv, bgr, cv::COLOR_HSV2BGR);
  return bgr.at<cv::Vec3b>(0, 0);
}

}  // namespace

void WriteGroundTruthPicture(const std::string& gt_path, GroundTruthStyle style,
                             const std::string& out_path, int max_width) {
  const cv::Mat labels = ReadGroundTruthLabels(gt_path, &style);
  const cv::Mat grey = ReadImageFile(gt_path, cv::IMREAD_GRAYSCALE);
  if (grey.empty() || grey.size() != labels.size()) {
    throw InputError("cannot read ground truth '" + gt_path + "' as an image");
  }
  cv::Mat picture(labels.size(), CV_8UC3);
  for (int r = 0; r < labels.rows; ++r) {
    for (int c = 0; c < labels.cols; ++c) {
      const int label = labels.at<int>(r, c);
      // Zones in colour; what is no zone stays dark (walls) or light grey.
      const uint8_t g = grey.at<uint8_t>(r, c) < 100 ? 0 : 200;
      picture.at<cv::Vec3b>(r, c) = label > 0 ? SegmentColour(label) : cv::Vec3b(g, g, g);
    }
  }
  if (max_width > 0 && picture.cols > max_width) {
    const double factor = static_cast<double>(max_width) / picture.cols;
    cv::resize(picture, picture, cv::Size(), factor, factor, cv::INTER_AREA);
  }
  WritePngFile(out_path, picture);
}

}  // namespace areagraph

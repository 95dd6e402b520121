#include "tools/eval/ground_truth_alignment.h"

#include <opencv2/imgproc.hpp>
#include <string>

#include "common/error.h"

namespace areagraph {

namespace {

std::string SizeText(cv::Size size) {
  return std::to_string(size.width) + "x" + std::to_string(size.height);
}

constexpr double kMinimumAgreement = 0.8;

}  // namespace

GroundTruthOffset FindGroundTruthOffset(const cv::Mat& gt_labels, const cv::Mat& result_labels) {
  const cv::Size gt_size = gt_labels.size(), result_size = result_labels.size();
  if (gt_size.width < result_size.width || gt_size.height < result_size.height) {
    throw InputError("ground truth is " + SizeText(gt_size) + " but the segmentation is " +
                     SizeText(result_size) + "; the ground truth must be at least as big");
  }
  // Agreement = pixels in a segment in both + pixels outside in both; each
  // term is a cross-correlation of masks, which matchTemplate computes fast.
  cv::Mat gt_inside, result_inside;
  cv::Mat(gt_labels != 0).convertTo(gt_inside, CV_32F, 1.0 / 255);
  cv::Mat(result_labels != 0).convertTo(result_inside, CV_32F, 1.0 / 255);
  const cv::Mat gt_outside = 1.0f - gt_inside, result_outside = 1.0f - result_inside;
  cv::Mat both_inside, both_outside;
  cv::matchTemplate(gt_inside, result_inside, both_inside, cv::TM_CCORR);
  cv::matchTemplate(gt_outside, result_outside, both_outside, cv::TM_CCORR);
  const cv::Mat agreement = both_inside + both_outside;
  double best = 0;
  cv::Point best_offset;
  cv::minMaxLoc(agreement, nullptr, &best, nullptr, &best_offset);
  GroundTruthOffset found{best_offset, best / static_cast<double>(result_labels.total())};
  if (found.agreement < kMinimumAgreement) {
    throw InputError("cannot align the " + SizeText(gt_size) + " ground truth with the " +
                     SizeText(result_size) + " segmentation (best offset agrees on " +
                     std::to_string(static_cast<int>(100 * found.agreement)) +
                     " % of the pixels); pass --gt-offset X,Y");
  }
  return found;
}

cv::Mat CropGroundTruth(const cv::Mat& gt_labels, cv::Size result_size, cv::Point offset) {
  const cv::Rect window(offset, result_size);
  if (offset.x < 0 || offset.y < 0 || window.br().x > gt_labels.cols ||
      window.br().y > gt_labels.rows) {
    throw InputError("the segmentation (" + SizeText(result_size) + ") at offset " +
                     std::to_string(offset.x) + "," + std::to_string(offset.y) +
                     " does not fit in the " + SizeText(gt_labels.size()) + " ground truth");
  }
  return gt_labels(window).clone();
}

}  // namespace areagraph

#pragma once

#include <opencv2/core.hpp>

namespace areagraph {

// Where a ground truth that is bigger than the segmentation lies under it:
// the segmentation's pixel (c, r) is the ground truth's (c + x, r + y).
struct GroundTruthOffset {
  cv::Point offset;
  // Share of the segmentation's pixels whose "in a segment" state agrees with
  // the ground truth's at that offset, in [0, 1].
  double agreement = 0;
};

// The offset at which the ground truth's segment mask agrees best with the
// segmentation's (both in a segment, or both outside). Used for GT images that
// were padded, like the Area Graph dataset's freiburg_building101 (x = 192).
// Throws InputError when the ground truth is smaller than the segmentation in
// either direction or when no offset agrees on at least 80 % of the pixels.
GroundTruthOffset FindGroundTruthOffset(const cv::Mat& gt_labels, const cv::Mat& result_labels);

// The part of `gt_labels` under the segmentation at `offset`; throws
// InputError when it does not fit.
cv::Mat CropGroundTruth(const cv::Mat& gt_labels, cv::Size result_size, cv::Point offset);

}  // namespace areagraph

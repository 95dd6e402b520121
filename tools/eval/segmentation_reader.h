#pragma once

#include <opencv2/core.hpp>
#include <string>

namespace areagraph {

// How to turn a segmentation image into labels.
enum class SegmentationReading {
  // 8- or 16-bit grey: each value > 0 is one segment. Colour images with
  // chromatic pixels: each chromatic colour is one segment, white/black/grey
  // are background. Colour images without any: their grey value.
  kAuto,
  // Like MAORIS' evaluation: cv::imread(IMREAD_GRAYSCALE) and every grey value
  // > 0 is one segment, so distinct colours with the same luma merge.
  kGreyLikeMaoris,
};

// Labels (CV_32S) of the segmentation image at `path`. Throws InputError when
// it is missing or not an image.
cv::Mat ReadSegmentationLabels(const std::string& path, SegmentationReading reading);

}  // namespace areagraph

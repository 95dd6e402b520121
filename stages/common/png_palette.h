#pragma once

#include <opencv2/core.hpp>
#include <optional>
#include <vector>

namespace areagraph {

// A BGR picture of at most 256 colours as one palette index per pixel:
// PNG stores such a picture as a palette (1 to 8 bits per pixel instead of
// 24), which is what makes maps and flat drawings cheap to encode.
struct PalettePicture {
  cv::Mat indices;                 // CV_8UC1, the same size as the picture
  std::vector<cv::Vec3b> colours;  // BGR, in the order they first appear
};

// The picture's palette form, or nothing when it has more than 256 colours
// (it stops at the 257th, so a busy picture costs part of one pass).
std::optional<PalettePicture> ToPalette(const cv::Mat& bgr);

// The palette form of the BGR picture whose pixels are the greys of `grey`
// (CV_8UC1) on all three channels: the same as ToPalette of that picture,
// without making it (a grey map is a third of the bytes to look at).
PalettePicture GreyToPalette(const cv::Mat& grey);

// The fewest PNG bits per index (1, 2, 4 or 8) that hold `colours` colours.
int PaletteBitDepth(size_t colours);

}  // namespace areagraph

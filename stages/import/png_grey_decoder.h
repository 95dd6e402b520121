#pragma once

#include <opencv2/core.hpp>
#include <string>

namespace areagraph {

// Decodes the common PNGs (no Exif chunk) to grey, 8-bit, or 16-bit for
// 16-bit samples (published maps come as 16-bit RGBA), with libpng directly, asking it for the very
// transformations that cv::imdecode(IMREAD_GRAYSCALE | IMREAD_ANYDEPTH) asks for (alpha and
// transparency stripped, palette expanded, luma 0.299 R + 0.587 G + 0.114 B
// by libpng's rgb_to_gray), so the pixels are the same: ag-import then needs
// no OpenCV codecs, whose loading costs more than the decoding. Returns
// false, leaving `grey` empty, for anything else (Exif, damage of any
// kind): the caller decodes those with OpenCV, which also
// words the errors.
bool DecodeCommonPngToGrey(const std::string& bytes, cv::Mat* grey);

}  // namespace areagraph

#pragma once

#include <opencv2/core.hpp>
#include <string>

namespace areagraph {

// `image` (8- or 16-bit, 1, 3 or 4 channels) as PNG bytes; `compression` is
// zlib's level, 0-9. 8-bit images go through libpng directly (no codecs to
// load), others through OpenCV. Throws Error when neither can encode it.
std::string EncodePng(const cv::Mat& image, int compression);

// EncodePng at zlib's fastest level (1), written through WriteOutputFile,
// so "-", links, devices and full disks are handled as for every other
// output. Throws InputError naming `target` when it cannot be written.
void WritePngFile(const std::string& target, const cv::Mat& image);

// WritePngFile of the BGR picture whose pixels are the greys of `grey`
// (CV_8UC1), the same bytes, without making that picture.
void WriteGreyPngFileAsColour(const std::string& target, const cv::Mat& grey);

}  // namespace areagraph

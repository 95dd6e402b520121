#pragma once

#include <opencv2/core.hpp>
#include <string>

namespace areagraph {

// Encodes 8-bit images of 1 (grey), 3 (BGR) or 4 (BGRA) channels as PNG with
// libpng directly: OpenCV's encoder is reached only by loading its codecs
// (about 0.4 G instructions, more than drawing a picture), and it lets
// libpng try every row filter, which costs more than the deflate itself.
// `compression` is zlib's level (0-9); each row gets the filter `filters`
// names (libpng's PNG_FILTER_* bits, PNG_ALL_FILTERS for its heuristic).
// A BGR image of at most 256 colours is written with a palette (the same
// pixels when decoded, far fewer bytes to compress).
// Returns false, leaving `png` empty, for other depths or channel counts.
bool EncodePngWithLibpng(const cv::Mat& image, int compression, int filters, std::string* png);

// The PNG that EncodePngWithLibpng writes for the BGR picture whose pixels
// are the greys of `grey` (CV_8UC1) on all three channels, byte for byte,
// without making that picture: its palette comes from the greys directly.
bool EncodeGreyAsColourPng(const cv::Mat& grey, int compression, int filters, std::string* png);

}  // namespace areagraph

#pragma once

#include <cstdint>
#include <opencv2/core.hpp>
#include <string>

namespace areagraph {

// Decodes an image file's bytes the way Bormann's room segmentation loads
// maps, cv::imread(path, IMREAD_GRAYSCALE | IMREAD_ANYDEPTH): alpha is
// dropped, colour becomes luma (Y), 16-bit samples are scaled to 8 bits (/257).
// Every format that OpenCV reads works (PNG, PGM, BMP, TIFF, JPEG, ...).
//
// Returns a CV_8UC1 image with at least one pixel. Throws InputError naming
// `path` for an empty, truncated, corrupt or unreadable file, and for images
// with more than `max_pixels` pixels (for PNG judged from the header before
// decoding, so a decompression bomb is never expanded).
cv::Mat DecodeGreyImage(const std::string& bytes, const std::string& path, int64_t max_pixels);

}  // namespace areagraph

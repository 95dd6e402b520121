#pragma once

#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <string>

namespace areagraph {

// Segmentations and ground truths are compared as label images: CV_32S, one
// int per pixel, 0 = no segment, any other value = the segment's label.

// The image at `path` as stored (8 or 16 bit, 1, 3 or 4 channels, BGR order),
// or as cv::imread's `imread_flags` turn it (IMREAD_GRAYSCALE). Throws
// InputError when the file is missing, not a regular file or not an image.
cv::Mat ReadImageFile(const std::string& path, int imread_flags = cv::IMREAD_UNCHANGED);

// True for a BGR pixel whose channels are not all equal.
inline bool IsChromatic(const cv::Vec3b& bgr) { return bgr[0] != bgr[1] || bgr[1] != bgr[2]; }

// The number of chromatic pixels of an 8-bit colour image (0 for grey images).
int CountChromaticPixels(const cv::Mat& image);

// One label per distinct chromatic colour (numbered in order of first
// appearance, row by row); white, black and greys become 0. Alpha is ignored.
cv::Mat LabelsFromColours(const cv::Mat& image);

// Grey values > 0 of a one-channel 8- or 16-bit image become labels as they
// are. Colour images use their first channel.
cv::Mat LabelsFromGreyValues(const cv::Mat& image);

// The image as 8-bit grey, the way cv::imread(path, IMREAD_GRAYSCALE) would
// give it: Y = 0.299 R + 0.587 G + 0.114 B, alpha dropped, 16 bit scaled down.
cv::Mat ToGrey8(const cv::Mat& image);

// Sets to 0 every label that covers `max_pixels` pixels or fewer in all.
void DropSmallSegments(cv::Mat* labels, int max_pixels);

// The number of distinct labels > 0.
int CountSegments(const cv::Mat& labels);

}  // namespace areagraph

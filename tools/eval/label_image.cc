#include "tools/eval/label_image.h"

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <set>
#include <unordered_map>

#include "common/error.h"
#include "common/input_file.h"

namespace areagraph {

cv::Mat ReadImageFile(const std::string& path, int imread_flags) {
  // The bytes through ReadInputFile, which refuses a FIFO or a device at once
  // instead of blocking on it as cv::imread would.
  const std::string bytes = ReadInputFile(path, "image '" + path + "'");
  cv::Mat image;
  if (!bytes.empty()) {
    image = cv::imdecode(
        cv::Mat(1, static_cast<int>(bytes.size()), CV_8U, const_cast<char*>(bytes.data())),
        imread_flags);
  }
  if (image.empty()) throw InputError("cannot read '" + path + "' as an image");
  if (image.depth() != CV_8U && image.depth() != CV_16U) {
    throw InputError("image '" + path + "' is neither 8 nor 16 bit per channel");
  }
  return image;
}

namespace {

// The colour channels of an 8-bit image as BGR (grey images repeat the value).
cv::Mat ToBgr8(const cv::Mat& image) {
  cv::Mat eight = image;
  if (image.depth() == CV_16U) image.convertTo(eight, CV_8U, 1.0 / 257.0);
  cv::Mat bgr;
  if (eight.channels() == 1) {
    cv::cvtColor(eight, bgr, cv::COLOR_GRAY2BGR);
  } else if (eight.channels() == 4) {
    cv::cvtColor(eight, bgr, cv::COLOR_BGRA2BGR);
  } else {
    bgr = eight;
  }
  return bgr;
}

}  // namespace

int CountChromaticPixels(const cv::Mat& image) {
  if (image.channels() < 3) return 0;
  const cv::Mat bgr = ToBgr8(image);
  int count = 0;
  for (int r = 0; r < bgr.rows; ++r) {
    const cv::Vec3b* row = bgr.ptr<cv::Vec3b>(r);
    for (int c = 0; c < bgr.cols; ++c) count += IsChromatic(row[c]) ? 1 : 0;
  }
  return count;
}

cv::Mat LabelsFromColours(const cv::Mat& image) {
  const cv::Mat bgr = ToBgr8(image);
  cv::Mat labels(bgr.size(), CV_32S, cv::Scalar(0));
  std::unordered_map<uint32_t, int> label_of_colour;
  for (int r = 0; r < bgr.rows; ++r) {
    const cv::Vec3b* row = bgr.ptr<cv::Vec3b>(r);
    int* out = labels.ptr<int>(r);
    for (int c = 0; c < bgr.cols; ++c) {
      if (!IsChromatic(row[c])) continue;
      const uint32_t key = row[c][0] | (row[c][1] << 8) | (row[c][2] << 16);
      auto [it, inserted] = label_of_colour.emplace(key, 0);
      if (inserted) it->second = static_cast<int>(label_of_colour.size());
      out[c] = it->second;
    }
  }
  return labels;
}

cv::Mat LabelsFromGreyValues(const cv::Mat& image) {
  cv::Mat channel = image;
  if (image.channels() > 1) cv::extractChannel(image, channel, 0);
  cv::Mat labels;
  channel.convertTo(labels, CV_32S);
  return labels;
}

cv::Mat ToGrey8(const cv::Mat& image) {
  cv::Mat eight = image;
  if (image.depth() == CV_16U) image.convertTo(eight, CV_8U, 1.0 / 257.0);
  cv::Mat grey;
  if (eight.channels() == 3) {
    cv::cvtColor(eight, grey, cv::COLOR_BGR2GRAY);
  } else if (eight.channels() == 4) {
    cv::cvtColor(eight, grey, cv::COLOR_BGRA2GRAY);
  } else {
    grey = eight;
  }
  return grey;
}

void DropSmallSegments(cv::Mat* labels, int max_pixels) {
  CV_Assert(labels->type() == CV_32S);
  std::unordered_map<int, int64_t> pixels;
  for (int r = 0; r < labels->rows; ++r) {
    const int* row = labels->ptr<int>(r);
    // Runs of one label are common: count them without a lookup per pixel.
    for (int c = 0; c < labels->cols;) {
      int end = c + 1;
      while (end < labels->cols && row[end] == row[c]) ++end;
      if (row[c] != 0) pixels[row[c]] += end - c;
      c = end;
    }
  }
  std::unordered_map<int, bool> small;
  for (const auto& [label, count] : pixels) small[label] = count <= max_pixels;
  for (int r = 0; r < labels->rows; ++r) {
    int* row = labels->ptr<int>(r);
    for (int c = 0; c < labels->cols; ++c) {
      if (row[c] != 0 && small[row[c]]) row[c] = 0;
    }
  }
}

int CountSegments(const cv::Mat& labels) {
  std::set<int> seen;
  for (auto it = labels.begin<int>(); it != labels.end<int>(); ++it) {
    if (*it != 0) seen.insert(*it);
  }
  return static_cast<int>(seen.size());
}

}  // namespace areagraph

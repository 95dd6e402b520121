#include "stages/import/grey_image.h"

#include <mutex>
#include <opencv2/imgcodecs.hpp>  // the IMREAD_ flags
#include <sstream>
#include <vector>

#include "common/error.h"
#include "common/png_header.h"
#include "common/stderr_capture.h"
#include "stages/common/image_codecs.h"
#include "stages/import/png_grey_decoder.h"

namespace areagraph {
namespace {

void CheckPixelCount(int64_t width, int64_t height, int64_t max_pixels, const std::string& path) {
  if (width <= 0 || height <= 0) {
    throw InputError("image '" + path + "' has no pixels (" + std::to_string(width) + "x" +
                     std::to_string(height) + ")");
  }
  if (width * height > max_pixels) {
    throw InputError("image '" + path + "' has " + std::to_string(width) + "x" +
                     std::to_string(height) +
                     " pixels, more than import.max_pixels = " + std::to_string(max_pixels));
  }
}

// The first "libpng error: ..." line of the decoder's output, if any: it says
// what exactly is wrong with a corrupt PNG.
std::string LibpngError(const std::string& decoder_output) {
  std::istringstream lines(decoder_output);
  for (std::string line; std::getline(lines, line);) {
    if (line.rfind("libpng error: ", 0) == 0) return line.substr(14);
  }
  return {};
}

cv::Mat DecodeQuietly(const std::string& bytes, const std::string& path) {
  // The capture redirects a process-wide descriptor: one decode at a time.
  static std::mutex decode_mutex;
  std::lock_guard<std::mutex> lock(decode_mutex);
  ScopedStderrCapture capture;
  cv::Mat image;
  try {
    image = DecodeImage(bytes, cv::IMREAD_GRAYSCALE | cv::IMREAD_ANYDEPTH);
  } catch (const cv::Exception& e) {
    throw InputError("cannot decode image '" + path + "': OpenCV check failed: " + e.err);
  }
  if (image.empty()) {
    const std::string libpng = LibpngError(capture.Text());
    throw InputError("cannot decode image '" + path + "': " +
                     (libpng.empty() ? "it is truncated or corrupt, or has no pixels" : libpng));
  }
  return image;
}

}  // namespace

cv::Mat DecodeGreyImage(const std::string& bytes, const std::string& path, int64_t max_pixels) {
  if (bytes.empty()) throw InputError("image file '" + path + "' is empty");
  if (HasPngSignature(bytes)) {
    const PngHeader header = ReadPngHeader(bytes, path);
    CheckPixelCount(header.width, header.height, max_pixels, path);
    if (!header.complete) throw InputError("PNG file '" + path + "' is truncated");
  } else if (!HaveImageReader(path)) {
    throw InputError("'" + path + "' is not an image that OpenCV can read (PNG, PGM, BMP, ...)");
  }

  cv::Mat image;
  if (!DecodeCommonPngToGrey(bytes, &image)) image = DecodeQuietly(bytes, path);
  CheckPixelCount(image.cols, image.rows, max_pixels, path);
  switch (image.depth()) {
    case CV_8U:
      return image;
    case CV_16U: {
      cv::Mat grey;
      image.convertTo(grey, CV_8U, 1.0 / 257.0);
      return grey;
    }
    default:
      throw InputError("image '" + path + "' has samples that are neither 8- nor 16-bit integers");
  }
}

}  // namespace areagraph

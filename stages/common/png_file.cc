#include "stages/common/png_file.h"

#include <png.h>  // the PNG_FILTER_ constants

#include <opencv2/imgcodecs.hpp>  // the IMWRITE_ constants only
#include <vector>

#include "common/error.h"
#include "stages/common/image_codecs.h"
#include "stages/common/output_file.h"
#include "stages/common/png_encoder.h"

namespace areagraph {

std::string EncodePng(const cv::Mat& image, int compression) {
  // Every row "up" (the difference to the row above): the pictures are flat
  // colours, where it is within 5-10 % of libpng's per-row choice of filter
  // (OpenCV's way) at 40 % less encoding work, and no codecs are loaded.
  std::string png;
  if (EncodePngWithLibpng(image, compression, PNG_FILTER_UP, &png)) return png;
  std::vector<uchar> bytes;
  bool encoded = false;
  try {
    encoded = EncodeImage(".png", image, &bytes, {cv::IMWRITE_PNG_COMPRESSION, compression});
  } catch (const cv::Exception& error) {
    throw Error("cannot encode the picture as PNG: " + error.msg);
  }
  if (!encoded) throw Error("cannot encode the picture as PNG");
  return std::string(bytes.begin(), bytes.end());
}

void WritePngFile(const std::string& target, const cv::Mat& image) {
  // zlib's fastest level: with the "up" filter, ag-render's pictures of a scan
  // come out 10-15 % larger than at level 6 (the import's twice, 45 kB) for
  // half the encoding work, which was most of a render.
  WriteOutputFile(target, EncodePng(image, 1));
}

void WriteGreyPngFileAsColour(const std::string& target, const cv::Mat& grey) {
  std::string png;
  if (!EncodeGreyAsColourPng(grey, 1, PNG_FILTER_UP, &png)) {
    throw Error("cannot encode the picture as PNG");
  }
  WriteOutputFile(target, png);
}

}  // namespace areagraph

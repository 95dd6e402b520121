// The import picture written from the cells (EncodeMapPng): the pixels of
// the canvas's greys, at every scale, with 1 or 2 bits per pixel.
#include "tools/render/map_png.h"

#include <gtest/gtest.h>

#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <string>
#include <vector>

#include "proto/artifacts.pb.h"
#include "tools/render/canvas.h"

namespace areagraph {
namespace {

cv::Mat Decoded(const std::string& png) {
  const std::vector<uchar> bytes(png.begin(), png.end());
  return cv::imdecode(bytes, cv::IMREAD_UNCHANGED);
}

// The BGR picture of the canvas's greys: what the canvas path wrote.
cv::Mat CanvasPicture(const std::string& cells, int width, int height, int scale) {
  Canvas canvas(cells, width, height, scale);
  cv::Mat bgr;
  cv::cvtColor(canvas.UntouchedGrey(), bgr, cv::COLOR_GRAY2BGR);
  return bgr;
}

// Byte 24 of a PNG: the IHDR's bits per sample (per palette index here).
int BitDepth(const std::string& png) { return static_cast<uint8_t>(png.at(24)); }

TEST(MapPng, DecodesToTheCanvasGreysAtEveryScale) {
  const int width = 37, height = 23;
  cv::Mat states(height, width, CV_8UC1);
  cv::randu(states, 0, 4);  // free, occupied, unknown and 3 (drawn as unknown)
  // The first cells are occupied, unknown, free: the palette's order is
  // not the states' order.
  states.at<uint8_t>(0, 0) = proto::CELL_OCCUPIED;
  states.at<uint8_t>(0, 1) = 3;
  std::string cells(states.ptr<char>(), states.ptr<char>() + states.total());
  cells.resize(cells.size() - 11);  // the last 11 cells are missing: unknown
  for (int scale = 1; scale <= 16; ++scale) {
    const std::string png = EncodeMapPng(cells, width, height, scale);
    EXPECT_EQ(BitDepth(png), 2) << scale;
    const cv::Mat picture = Decoded(png);
    const cv::Mat expected = CanvasPicture(cells, width, height, scale);
    ASSERT_EQ(picture.size(), expected.size()) << scale;
    ASSERT_EQ(picture.type(), CV_8UC3) << scale;
    EXPECT_EQ(cv::norm(picture, expected, cv::NORM_INF), 0) << "scale " << scale;
  }
}

TEST(MapPng, TwoGreysTakeOneBitPerPixel) {
  // 13 columns: rows that do not fill their last byte.
  const int width = 13, height = 5;
  std::string cells(width * height, static_cast<char>(proto::CELL_FREE));
  for (size_t i = 0; i < cells.size(); i += 4) cells[i] = static_cast<char>(proto::CELL_OCCUPIED);
  for (const int scale : {1, 3}) {
    const std::string png = EncodeMapPng(cells, width, height, scale);
    EXPECT_EQ(BitDepth(png), 1);
    const cv::Mat picture = Decoded(png);
    EXPECT_EQ(cv::norm(picture, CanvasPicture(cells, width, height, scale), cv::NORM_INF), 0);
    EXPECT_EQ(picture.at<cv::Vec3b>(0, 0),
              cv::Vec3b(kOccupiedCellGrey, kOccupiedCellGrey, kOccupiedCellGrey));
    EXPECT_EQ(picture.at<cv::Vec3b>(0, scale),
              cv::Vec3b(kFreeCellGrey, kFreeCellGrey, kFreeCellGrey));
  }
}

}  // namespace
}  // namespace areagraph

// PNGs written with libpng directly (png_encoder.h) and through EncodePng:
// OpenCV's decoder must give back every pixel and channel.
#include "stages/common/png_encoder.h"

#include <gtest/gtest.h>
#include <png.h>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <string>
#include <vector>

#include "stages/common/png_file.h"

namespace areagraph::testing {
namespace {

// A picture with a different value in every sample, so that a swapped
// channel or a shifted row shows.
cv::Mat Varied(int type) {
  cv::Mat image(7, 5, type);
  cv::randu(image, cv::Scalar::all(0), cv::Scalar::all(type == CV_16UC1 ? 65535 : 255));
  return image;
}

cv::Mat Decode(const std::string& png) {
  const std::vector<uchar> bytes(png.begin(), png.end());
  return cv::imdecode(bytes, cv::IMREAD_UNCHANGED);
}

bool SamePixels(const cv::Mat& a, const cv::Mat& b) {
  return a.size() == b.size() && a.type() == b.type() && cv::norm(a, b, cv::NORM_INF) == 0;
}

TEST(PngEncoder, GivesBackGreyBgrAndBgraPixelsWithEveryFilterAndLevel) {
  for (const int type : {CV_8UC1, CV_8UC3, CV_8UC4}) {
    const cv::Mat image = Varied(type);
    for (const int filters : {PNG_FILTER_NONE, PNG_FILTER_UP, PNG_ALL_FILTERS}) {
      for (const int level : {0, 1, 9}) {
        std::string png;
        ASSERT_TRUE(EncodePngWithLibpng(image, level, filters, &png));
        EXPECT_TRUE(SamePixels(Decode(png), image)) << type << " " << filters << " " << level;
      }
    }
  }
}

TEST(PngEncoder, RefusesWhatItDoesNotWrite) {
  std::string png = "left over";
  EXPECT_FALSE(EncodePngWithLibpng(Varied(CV_16UC1), 1, PNG_FILTER_UP, &png));
  EXPECT_TRUE(png.empty());
  EXPECT_FALSE(EncodePngWithLibpng(cv::Mat(3, 3, CV_8UC2, cv::Scalar::all(1)), 1, 0, &png));
  EXPECT_FALSE(EncodePngWithLibpng(cv::Mat(), 1, 0, &png));
}

TEST(PngEncoder, EncodePngWritesSixteenBitThroughOpenCv) {
  const cv::Mat deep = Varied(CV_16UC1);
  EXPECT_TRUE(SamePixels(Decode(EncodePng(deep, 1)), deep));
  const cv::Mat colour = Varied(CV_8UC3);
  EXPECT_TRUE(SamePixels(Decode(EncodePng(colour, 1)), colour));
}

TEST(PngEncoder, AGreyPictureWrittenAsColourIsTheFileOfItsBgrPicture) {
  // A map's three greys, upscaled (every row has a twin), and a picture of
  // random greys (many palette entries, the order they first appear in).
  cv::Mat map(4, 6, CV_8UC1);
  const uchar greys[] = {200, 255, 40};
  for (int i = 0; i < map.rows * map.cols; ++i) map.data[i] = greys[(i * 7 + i / 5) % 3];
  cv::Mat upscaled;
  cv::resize(map, upscaled, cv::Size(), 3, 3, cv::INTER_NEAREST);
  cv::Mat random(9, 11, CV_8UC1);
  cv::randu(random, cv::Scalar::all(0), cv::Scalar::all(256));
  for (const cv::Mat& grey : {map, upscaled, random}) {
    cv::Mat bgr;
    cv::cvtColor(grey, bgr, cv::COLOR_GRAY2BGR);
    std::string from_bgr, from_grey;
    ASSERT_TRUE(EncodePngWithLibpng(bgr, 1, PNG_FILTER_UP, &from_bgr));
    ASSERT_TRUE(EncodeGreyAsColourPng(grey, 1, PNG_FILTER_UP, &from_grey));
    EXPECT_EQ(from_grey, from_bgr);
    EXPECT_TRUE(SamePixels(Decode(from_grey), bgr));
  }
}

}  // namespace
}  // namespace areagraph::testing

// Pictures of at most 256 colours are written with a palette (fewer bits per
// pixel), busier ones as RGB; both decode to the very same pixels.
#include "stages/common/png_palette.h"

#include <gtest/gtest.h>
#include <png.h>

#include <opencv2/imgcodecs.hpp>
#include <string>
#include <vector>

#include "stages/common/png_encoder.h"

namespace areagraph::testing {
namespace {

// An 80 x 30 BGR picture whose pixels cycle through `colours` distinct
// colours in runs of 3, every row twice (as an upscaled picture has them).
cv::Mat Picture(int colours) {
  cv::Mat image(30, 80, CV_8UC3);
  for (int y = 0; y < image.rows; ++y) {
    for (int x = 0; x < image.cols; ++x) {
      const int c = ((y / 2) * image.cols + x) / 3 % colours;
      image.at<cv::Vec3b>(y, x) = cv::Vec3b(c % 7 * 30, c / 7 % 7 * 30, c / 49 * 40);
    }
  }
  return image;
}

// The IHDR's bit depth and colour type (bytes 24 and 25 of a PNG).
std::pair<int, int> DepthAndColourType(const std::string& png) {
  return {static_cast<uint8_t>(png.at(24)), static_cast<uint8_t>(png.at(25))};
}

cv::Mat Decode(const std::string& png) {
  const std::vector<uchar> bytes(png.begin(), png.end());
  return cv::imdecode(bytes, cv::IMREAD_UNCHANGED);
}

TEST(PngPalette, FewColoursAreWrittenWithTheSmallestPalette) {
  for (const auto& [colours, depth] : std::vector<std::pair<int, int>>{
           {1, 1}, {2, 1}, {3, 2}, {4, 2}, {5, 4}, {16, 4}, {17, 8}, {256, 8}}) {
    const cv::Mat image = Picture(colours);
    std::string png;
    ASSERT_TRUE(EncodePngWithLibpng(image, 1, PNG_FILTER_UP, &png));
    EXPECT_EQ(DepthAndColourType(png), std::make_pair(depth, int{PNG_COLOR_TYPE_PALETTE}))
        << colours;
    const cv::Mat decoded = Decode(png);
    ASSERT_EQ(decoded.type(), CV_8UC3) << colours;
    EXPECT_EQ(cv::norm(decoded, image, cv::NORM_INF), 0) << colours;
  }
}

TEST(PngPalette, TheTwoHundredAndFiftySeventhColourMakesItRgb) {
  const cv::Mat image = Picture(257);
  EXPECT_FALSE(ToPalette(image).has_value());
  std::string png;
  ASSERT_TRUE(EncodePngWithLibpng(image, 1, PNG_FILTER_UP, &png));
  EXPECT_EQ(DepthAndColourType(png), std::make_pair(8, int{PNG_COLOR_TYPE_RGB}));
  EXPECT_EQ(cv::norm(Decode(png), image, cv::NORM_INF), 0);
}

TEST(PngPalette, IndicesPointAtEachPixelsColour) {
  const cv::Mat image = Picture(20);
  const std::optional<PalettePicture> palette = ToPalette(image);
  ASSERT_TRUE(palette.has_value());
  EXPECT_EQ(palette->colours.size(), 20u);
  for (int y = 0; y < image.rows; ++y) {
    for (int x = 0; x < image.cols; ++x) {
      ASSERT_EQ(palette->colours.at(palette->indices.at<uint8_t>(y, x)), image.at<cv::Vec3b>(y, x))
          << x << "," << y;
    }
  }
  EXPECT_FALSE(ToPalette(cv::Mat(3, 3, CV_8UC1, cv::Scalar(1))).has_value());
}

}  // namespace
}  // namespace areagraph::testing

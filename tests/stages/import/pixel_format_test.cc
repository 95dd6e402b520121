// Every pixel format decodes to the same cells: the grey value decides, alpha
// is ignored, 16-bit samples count as their top 8 bits (/257).
#include <gtest/gtest.h>

#include <opencv2/imgcodecs.hpp>
#include <string>
#include <vector>

#include "stages/import/import_stage.h"
#include "tests/stages/import/test_png_writer.h"
#include "tests/support/test_support.h"

namespace areagraph {
namespace {

using testing::TempDir;
using testing::WriteFile;

constexpr proto::CellState F = proto::CELL_FREE;
constexpr proto::CellState O = proto::CELL_OCCUPIED;
constexpr proto::CellState U = proto::CELL_UNKNOWN;

// Grey values around the default thresholds (occupied <= 100, free >= 250)
// and the classes they must get. The second row is the first reversed, so a
// transposed or flipped decode fails too.
const std::vector<int> kGreys = {0, 37, 100, 101, 127, 205, 249, 250, 254, 255};
const std::vector<proto::CellState> kClasses = {O, O, O, U, U, U, U, F, F, F};
constexpr int kWidth = 10, kHeight = 2;

int GreyAt(int row, int col) { return kGreys[row == 0 ? col : kWidth - 1 - col]; }

std::string ExpectedCells() {
  std::string cells;
  for (int row = 0; row < kHeight; ++row) {
    for (int col = 0; col < kWidth; ++col) {
      cells.push_back(static_cast<char>(kClasses[row == 0 ? col : kWidth - 1 - col]));
    }
  }
  return cells;
}

proto::GridMap Import(const std::string& path) {
  return ImportGridMap(ReadImportSource(path), proto::ImportOptions());
}

void ExpectTestPattern(const std::string& path) {
  const proto::GridMap grid = Import(path);
  EXPECT_EQ(grid.frame().width_px(), kWidth);
  EXPECT_EQ(grid.frame().height_px(), kHeight);
  EXPECT_DOUBLE_EQ(grid.frame().resolution_m(), 0.05);
  EXPECT_EQ(grid.cells(), ExpectedCells()) << path;
}

// The test pattern as an image of `type` (1, 3 or 4 channels), samples
// multiplied by `scale`; with `alpha` >= 0 the fourth channel varies.
cv::Mat Pattern(int type, double scale, int alpha = -1) {
  cv::Mat image(kHeight, kWidth, type);
  for (int row = 0; row < kHeight; ++row) {
    for (int col = 0; col < kWidth; ++col) {
      const double grey = GreyAt(row, col) * scale;
      // Alpha varies from pixel to pixel, transparent ones included.
      const double alpha_value = alpha < 0 ? 0 : ((row * kWidth + col) * 29 % 256) * scale;
      image(cv::Rect(col, row, 1, 1)).setTo(cv::Scalar(grey, grey, grey, alpha_value));
    }
  }
  return image;
}

TEST(PixelFormatTest, EightBitGreyPng) {
  TempDir dir;
  ASSERT_TRUE(cv::imwrite(dir.File("grey8.png"), Pattern(CV_8UC1, 1)));
  ExpectTestPattern(dir.File("grey8.png"));
}

TEST(PixelFormatTest, SixteenBitGreyPngScalesBy257) {
  TempDir dir;
  ASSERT_TRUE(cv::imwrite(dir.File("grey16.png"), Pattern(CV_16UC1, 257)));
  ExpectTestPattern(dir.File("grey16.png"));
}

TEST(PixelFormatTest, SixteenBitValuesRoundToNearestEightBit) {
  // 25828 / 257 = 100.5 rounds to 101 (unknown); 25827 / 257 = 100.49 to 100.
  TempDir dir;
  cv::Mat image(1, 2, CV_16UC1);
  image.at<uint16_t>(0, 0) = 25827;
  image.at<uint16_t>(0, 1) = 25829;
  ASSERT_TRUE(cv::imwrite(dir.File("round.png"), image));
  EXPECT_EQ(Import(dir.File("round.png")).cells(), std::string({O, U}));
}

TEST(PixelFormatTest, RgbPng) {
  TempDir dir;
  ASSERT_TRUE(cv::imwrite(dir.File("rgb.png"), Pattern(CV_8UC3, 1)));
  ExpectTestPattern(dir.File("rgb.png"));
}

TEST(PixelFormatTest, RgbaPngIgnoresAlpha) {
  TempDir dir;
  ASSERT_TRUE(cv::imwrite(dir.File("rgba.png"), Pattern(CV_8UC4, 1, /*alpha=*/1)));
  ExpectTestPattern(dir.File("rgba.png"));
}

TEST(PixelFormatTest, SixteenBitRgbaPng) {
  TempDir dir;
  ASSERT_TRUE(cv::imwrite(dir.File("rgba16.png"), Pattern(CV_16UC4, 257, /*alpha=*/1)));
  ExpectTestPattern(dir.File("rgba16.png"));
}

TEST(PixelFormatTest, ColoursBecomeLuma) {
  // BGR order. Luma: blue 29 and red 76 are occupied; green 150, cyan 179 and
  // yellow 226 unknown; white free.
  TempDir dir;
  cv::Mat image(1, 6, CV_8UC3);
  const cv::Vec3b colours[] = {{255, 0, 0},   {0, 0, 255},   {0, 255, 0},
                               {255, 255, 0}, {0, 255, 255}, {255, 255, 255}};
  for (int col = 0; col < 6; ++col) image.at<cv::Vec3b>(0, col) = colours[col];
  ASSERT_TRUE(cv::imwrite(dir.File("colours.png"), image));
  EXPECT_EQ(Import(dir.File("colours.png")).cells(), std::string({O, O, U, U, U, F}));
}

TEST(PixelFormatTest, PgmAndBmp) {
  TempDir dir;
  ASSERT_TRUE(cv::imwrite(dir.File("grey.pgm"), Pattern(CV_8UC1, 1)));
  ExpectTestPattern(dir.File("grey.pgm"));
  ASSERT_TRUE(cv::imwrite(dir.File("grey16.pgm"), Pattern(CV_16UC1, 257)));
  ExpectTestPattern(dir.File("grey16.pgm"));
  ASSERT_TRUE(cv::imwrite(dir.File("rgb.bmp"), Pattern(CV_8UC3, 1)));
  ExpectTestPattern(dir.File("rgb.bmp"));
}

TEST(PixelFormatTest, PalettePngWithTransparency) {
  // Palette: the ten test greys, then pure red and pure green.
  std::vector<uint8_t> palette;
  for (const int grey : kGreys) palette.insert(palette.end(), 3, static_cast<uint8_t>(grey));
  palette.insert(palette.end(), {255, 0, 0, 0, 255, 0});
  std::vector<uint8_t> indices;
  for (int row = 0; row < kHeight; ++row) {
    for (int col = 0; col < kWidth; ++col) indices.push_back(row == 0 ? col : kWidth - 1 - col);
  }
  // A third row: red, green, then transparent white (index 9, alpha 0).
  indices.insert(indices.end(), {10, 11, 9, 9, 9, 9, 9, 9, 9, 9});
  std::vector<uint8_t> alpha(12, 255);
  alpha[9] = 0;
  TempDir dir;
  WriteFile(dir.File("palette.png"),
            testing::PalettePng(kWidth, kHeight + 1, indices, palette, alpha));

  const proto::GridMap grid = Import(dir.File("palette.png"));
  ASSERT_EQ(grid.frame().height_px(), kHeight + 1);
  EXPECT_EQ(grid.cells().substr(0, kWidth * kHeight), ExpectedCells());
  EXPECT_EQ(grid.cells().substr(kWidth * kHeight), std::string({O, U, F, F, F, F, F, F, F, F}));
}

TEST(PixelFormatTest, GreyAlphaPng8And16Bit) {
  for (const int bit_depth : {8, 16}) {
    std::vector<uint16_t> samples;
    const int scale = bit_depth == 16 ? 257 : 1;
    for (int row = 0; row < kHeight; ++row) {
      for (int col = 0; col < kWidth; ++col) {
        samples.push_back(static_cast<uint16_t>(GreyAt(row, col) * scale));
        samples.push_back(static_cast<uint16_t>(col % 2 == 0 ? 0 : 255 * scale));
      }
    }
    TempDir dir;
    WriteFile(dir.File("grey_alpha.png"),
              testing::GreyAlphaPng(kWidth, kHeight, samples, bit_depth));
    SCOPED_TRACE(bit_depth);
    ExpectTestPattern(dir.File("grey_alpha.png"));
  }
}

TEST(PixelFormatTest, ThresholdOptionsMoveTheBoundaries) {
  TempDir dir;
  ASSERT_TRUE(cv::imwrite(dir.File("grey8.png"), Pattern(CV_8UC1, 1)));
  proto::ImportOptions options;
  options.set_occupied_max_grey(127);
  options.set_free_min_grey(205);
  const proto::GridMap grid = ImportGridMap(ReadImportSource(dir.File("grey8.png")), options);
  // 0 37 100 101 127 | 205 249 250 254 255
  EXPECT_EQ(grid.cells().substr(0, kWidth), std::string({O, O, O, O, O, F, F, F, F, F}));
}

}  // namespace
}  // namespace areagraph

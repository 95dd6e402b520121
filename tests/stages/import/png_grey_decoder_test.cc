// ag-import decodes the common PNGs with libpng itself; the pixels must be
// exactly those of cv::imdecode(IMREAD_GRAYSCALE | IMREAD_ANYDEPTH).
#include "stages/import/png_grey_decoder.h"

#include <gtest/gtest.h>
#include <zlib.h>

#include <filesystem>
#include <fstream>
#include <opencv2/imgcodecs.hpp>
#include <random>
#include <sstream>

#include "stages/common/image_codecs.h"
#include "stages/import/png_fast_decoder.h"
#include "tests/stages/import/test_png_writer.h"
#include "tests/support/test_support.h"

namespace areagraph::testing {
namespace {

// True when libpng took `bytes` and gave OpenCV's pixels; false when it
// declined (OpenCV decodes those).
bool DecodesLikeOpenCv(const std::string& bytes, const std::string& what) {
  cv::Mat ours;
  if (!DecodeCommonPngToGrey(bytes, &ours)) {
    EXPECT_TRUE(ours.empty()) << what;
    return false;
  }
  const cv::Mat theirs = DecodeImage(bytes, cv::IMREAD_GRAYSCALE | cv::IMREAD_ANYDEPTH);
  EXPECT_EQ(ours.type(), theirs.type()) << what;
  EXPECT_EQ(ours.size(), theirs.size()) << what;
  if (ours.size() == theirs.size() && ours.type() == theirs.type()) {
    EXPECT_EQ(cv::countNonZero(ours != theirs), 0) << what;
  }
  return true;
}

std::string Encode(const cv::Mat& image) {
  std::vector<uchar> bytes;
  EXPECT_TRUE(EncodeImage(".png", image, &bytes));
  return std::string(bytes.begin(), bytes.end());
}

TEST(PngGreyDecoder, GreyRgbRgbaPaletteAndGreyAlphaAsOpenCv) {
  cv::Mat grey(7, 9, CV_8UC1), bgr(7, 9, CV_8UC3), bgra(7, 9, CV_8UC4);
  cv::randu(grey, 0, 256);
  cv::randu(bgr, 0, 256);
  cv::randu(bgra, 0, 256);
  EXPECT_TRUE(DecodesLikeOpenCv(Encode(grey), "grey"));
  EXPECT_TRUE(DecodesLikeOpenCv(Encode(bgr), "rgb"));
  EXPECT_TRUE(DecodesLikeOpenCv(Encode(bgra), "rgba"));
  EXPECT_TRUE(DecodesLikeOpenCv(
      PalettePng(2, 2, {0, 1, 2, 1}, {255, 0, 0, 0, 255, 0, 10, 20, 30}, {255, 0, 128}),
      "palette with transparency"));
  EXPECT_TRUE(DecodesLikeOpenCv(GreyAlphaPng(2, 1, {200, 0, 17, 255}, 8), "grey+alpha"));
}

TEST(PngGreyDecoder, SixteenBitGreyRgbRgbaAndGreyAlphaAsOpenCv) {
  cv::Mat grey(5, 6, CV_16UC1), bgr(5, 6, CV_16UC3), bgra(5, 6, CV_16UC4);
  cv::randu(grey, 0, 65536);
  cv::randu(bgr, 0, 65536);
  cv::randu(bgra, 0, 65536);
  EXPECT_TRUE(DecodesLikeOpenCv(Encode(grey), "16-bit grey"));
  EXPECT_TRUE(DecodesLikeOpenCv(Encode(bgr), "16-bit rgb"));
  EXPECT_TRUE(DecodesLikeOpenCv(Encode(bgra), "16-bit rgba"));
  EXPECT_TRUE(DecodesLikeOpenCv(GreyAlphaPng(1, 1, {1000, 65535}, 16), "16-bit grey+alpha"));
}

TEST(PngGreyDecoder, DeclinesDamagedFiles) {
  cv::Mat out;
  std::string truncated = Encode(cv::Mat(40, 40, CV_8UC1, cv::Scalar(3)));
  truncated.resize(truncated.size() / 2);
  EXPECT_FALSE(DecodeCommonPngToGrey(truncated, &out));
  EXPECT_TRUE(out.empty());
  EXPECT_FALSE(DecodeCommonPngToGrey("P5\n1 1\n255\n\x01", &out));
}

// The PNG with the last IDAT chunk's final four data bytes (the zlib
// stream's Adler-32) changed and that chunk's CRC-32 made right again.
std::string WithWrongAdler32(std::string png) {
  size_t last_idat = std::string::npos;
  for (size_t at = 8; at + 12 <= png.size();) {
    const uint32_t length = uint32_t(uint8_t(png[at])) << 24 |
                            uint32_t(uint8_t(png[at + 1])) << 16 |
                            uint32_t(uint8_t(png[at + 2])) << 8 | uint8_t(png[at + 3]);
    if (png.compare(at + 4, 4, "IDAT") == 0) last_idat = at;
    at += 12 + length;
  }
  EXPECT_NE(last_idat, std::string::npos);
  const uint32_t length = uint32_t(uint8_t(png[last_idat])) << 24 |
                          uint32_t(uint8_t(png[last_idat + 1])) << 16 |
                          uint32_t(uint8_t(png[last_idat + 2])) << 8 | uint8_t(png[last_idat + 3]);
  const size_t data_end = last_idat + 8 + length;
  png[data_end - 1] = char(png[data_end - 1] ^ 0x5a);
  const uLong crc =
      crc32(0, reinterpret_cast<const Bytef*>(png.data() + last_idat + 4), uInt(length + 4));
  for (int i = 0; i < 4; ++i) png[data_end + i] = char((crc >> (24 - 8 * i)) & 0xff);
  return png;
}

TEST(PngGreyDecoder, LeavesTheAdler32ToTheChunkCrcs) {
  // libpng skips zlib's Adler-32 (png_set_option PNG_IGNORE_ADLER32): the
  // chunk CRC-32s cover the same bytes. A stream whose Adler-32 alone is
  // wrong decodes to the right pixels; a chunk with a wrong CRC still fails.
  cv::Mat bgr(23, 31, CV_8UC3);
  cv::randu(bgr, 0, 256);
  const std::string good = Encode(bgr);
  const std::string wrong_adler = WithWrongAdler32(good);
  ASSERT_NE(good, wrong_adler);
  cv::Mat expected, decoded;
  ASSERT_TRUE(DecodeCommonPngToGrey(good, &expected));
  ASSERT_TRUE(DecodeCommonPngToGrey(wrong_adler, &decoded));
  EXPECT_EQ(cv::countNonZero(decoded != expected), 0);
  std::string wrong_crc = wrong_adler;
  wrong_crc[wrong_crc.size() - 13] = char(wrong_crc[wrong_crc.size() - 13] ^ 1);
  EXPECT_FALSE(DecodeCommonPngToGrey(wrong_crc, &decoded));
}

// The plain decoder takes `bytes` and gives OpenCV's (libpng's) pixels.
void ExpectPlainLikeOpenCv(const std::string& bytes, const std::string& what) {
  cv::Mat ours;
  ASSERT_TRUE(DecodePlainPngToGrey(bytes, &ours)) << what;
  const cv::Mat theirs = DecodeImage(bytes, cv::IMREAD_GRAYSCALE | cv::IMREAD_ANYDEPTH);
  ASSERT_EQ(ours.type(), theirs.type()) << what;
  ASSERT_EQ(ours.size(), theirs.size()) << what;
  EXPECT_EQ(cv::countNonZero(ours != theirs), 0) << what;
}

TEST(PlainPngDecoder, GreyRgbRgbaAndGreyAlphaAsLibpngOnEveryFilter) {
  // Smooth gradients with noise: libpng's encoder picks all five filters.
  std::mt19937 random(12);
  for (int trial = 0; trial < 12; ++trial) {
    const int rows = 1 + int(random() % 60), cols = 1 + int(random() % 90);
    cv::Mat bgr(rows, cols, CV_8UC3), bgra(rows, cols, CV_8UC4), grey(rows, cols, CV_8UC1);
    for (int r = 0; r < rows; ++r) {
      for (int c = 0; c < cols; ++c) {
        const int noise = int(random() % 7);
        bgr.at<cv::Vec3b>(r, c) = cv::Vec3b(uchar(3 * r + noise), uchar(2 * c), uchar(r + c));
        bgra.at<cv::Vec4b>(r, c) =
            cv::Vec4b(uchar(r * c), uchar(c + noise), uchar(5 * r), uchar(random() % 256));
        grey.at<uchar>(r, c) = uchar(trial % 2 ? random() % 256 : r + c + noise);
      }
    }
    // Greys (r = g = b) stay as they are: a third of the pixels grey.
    for (int r = 0; r < rows; r += 3) bgr.row(r).setTo(cv::Scalar(r, r, r));
    ExpectPlainLikeOpenCv(Encode(bgr), "rgb");
    ExpectPlainLikeOpenCv(Encode(bgra), "rgba");
    ExpectPlainLikeOpenCv(Encode(grey), "grey");
  }
  std::vector<uint16_t> grey_alpha;
  for (int i = 0; i < 4 * 3; ++i) grey_alpha.insert(grey_alpha.end(), {uint16_t(i * 20), 7});
  ExpectPlainLikeOpenCv(GreyAlphaPng(4, 3, grey_alpha, 8), "grey+alpha");
}

TEST(PlainPngDecoder, EveryFilterOfEveryColourTypeAsLibpng) {
  // Rows filtered 0..4 in turn, and all Paeth, on random and smooth samples:
  // every branch of each filter's predictor.
  std::mt19937 random(13);
  for (const int colour_type : {0, 4, 2, 6}) {
    const int channels = colour_type == 0 ? 1 : colour_type == 4 ? 2 : colour_type == 2 ? 3 : 4;
    for (int trial = 0; trial < 8; ++trial) {
      const int width = 1 + int(random() % 40), height = 1 + int(random() % 12);
      std::vector<uint8_t> pixels(size_t(width) * height * channels);
      for (size_t i = 0; i < pixels.size(); ++i) {
        pixels[i] = uint8_t(trial % 2 ? random() % 256 : i * 7 % 256 + random() % 3);
      }
      for (const std::vector<int>& filters : {std::vector<int>{0, 1, 2, 3, 4}, {4}, {3, 1}}) {
        ExpectPlainLikeOpenCv(FilteredPng(width, height, colour_type, pixels, filters),
                              "colour type " + std::to_string(colour_type));
      }
    }
  }
}

TEST(PlainPngDecoder, EveryColourAsLibpng) {
  // All 2^24 colours once: the luma coefficients and their truncation.
  cv::Mat bgr(4096, 4096, CV_8UC3);
  for (int r = 0; r < 4096; ++r) {
    for (int c = 0; c < 4096; ++c) {
      const int colour = r * 4096 + c;
      bgr.at<cv::Vec3b>(r, c) =
          cv::Vec3b(uchar(colour & 255), uchar((colour >> 8) & 255), uchar(colour >> 16));
    }
  }
  ExpectPlainLikeOpenCv(Encode(bgr), "every colour");
}

TEST(PlainPngDecoder, LeavesEverythingElseToLibpng) {
  cv::Mat out;
  cv::Mat bgr(5, 6, CV_8UC3, cv::Scalar(1, 2, 3)), deep(5, 6, CV_16UC1, cv::Scalar(1000));
  const std::string good = Encode(bgr);
  EXPECT_TRUE(DecodePlainPngToGrey(good, &out));
  EXPECT_FALSE(DecodePlainPngToGrey(Encode(deep), &out));
  EXPECT_TRUE(out.empty());
  EXPECT_FALSE(DecodePlainPngToGrey(PalettePng(2, 1, {0, 1}, {255, 0, 0, 0, 255, 0}), &out));
  // A gAMA chunk after IHDR (8 + 25 bytes), with its CRC: gamma is libpng's.
  std::string gamma = good;
  const std::string chunk("\0\0\0\4gAMA\0\0\xb1\x8f", 12);
  const uLong crc = crc32(0, reinterpret_cast<const Bytef*>(chunk.data() + 4), 8);
  std::string with_crc = chunk;
  for (int i = 0; i < 4; ++i) with_crc += char((crc >> (24 - 8 * i)) & 0xff);
  gamma.insert(33, with_crc);
  EXPECT_TRUE(DecodeCommonPngToGrey(gamma, &out));
  EXPECT_FALSE(DecodePlainPngToGrey(gamma, &out));
  // A wrong CRC anywhere, or data cut short.
  std::string bad_crc = good;
  bad_crc[29] = char(bad_crc[29] ^ 1);
  EXPECT_FALSE(DecodePlainPngToGrey(bad_crc, &out));
  EXPECT_FALSE(DecodePlainPngToGrey(good.substr(0, good.size() - 20), &out));
  EXPECT_TRUE(out.empty());
}

// Every PNG of ../shared/data (maps, ground truths, published results: grey,
// RGB, RGBA, palette) decodes to OpenCV's pixels.
TEST(PngGreyDecoder, EverySharedPngAsOpenCv) {
  if (!HaveSharedData()) GTEST_SKIP() << "no ../shared/data";
  int decoded = 0;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(SharedDataPath(""))) {
    if (!entry.is_regular_file() || entry.path().extension() != ".png") continue;
    std::ifstream file(entry.path(), std::ios::binary);
    std::stringstream bytes;
    bytes << file.rdbuf();
    decoded += DecodesLikeOpenCv(bytes.str(), entry.path().string());
  }
  EXPECT_GT(decoded, 100);
}

}  // namespace
}  // namespace areagraph::testing

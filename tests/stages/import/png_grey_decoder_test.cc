// ag-import decodes the common PNGs with libpng itself; the pixels must be
// exactly those of cv::imdecode(IMREAD_GRAYSCALE | IMREAD_ANYDEPTH).
#include "stages/import/png_grey_decoder.h"

#include <gtest/gtest.h>
#include <zlib.h>

#include <filesystem>
#include <fstream>
#include <opencv2/imgcodecs.hpp>
#include <sstream>

#include "stages/common/image_codecs.h"
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

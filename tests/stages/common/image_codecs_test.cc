// OpenCV's image codecs, loaded on first use from the module beside the
// executables (image_codecs.h).
#include "stages/common/image_codecs.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <opencv2/imgcodecs.hpp>
#include <string>

#include "tests/support/test_support.h"

namespace areagraph::testing {
namespace {

TEST(ImageCodecs, EncodeThenDecodeGivesThePixelsBack) {
  cv::Mat image(3, 4, CV_8UC1);
  for (int i = 0; i < 12; ++i) image.at<uchar>(i / 4, i % 4) = static_cast<uchar>(20 * i);
  std::vector<uchar> png;
  ASSERT_TRUE(EncodeImage(".png", image, &png, {cv::IMWRITE_PNG_COMPRESSION, 9}));
  ASSERT_GT(png.size(), 8u);
  EXPECT_EQ(png[1], 'P');
  const cv::Mat decoded = DecodeImage(std::string(png.begin(), png.end()), cv::IMREAD_GRAYSCALE);
  ASSERT_EQ(decoded.size(), image.size());
  EXPECT_EQ(cv::countNonZero(decoded != image), 0);
  EXPECT_TRUE(DecodeImage("not an image", cv::IMREAD_GRAYSCALE).empty());
}

TEST(ImageCodecs, KnowsWhichFilesItCanRead) {
  TempDir dir;
  const std::string png = dir.File("map.png"), text = dir.File("notes.txt");
  std::vector<uchar> bytes;
  ASSERT_TRUE(EncodeImage(".png", cv::Mat(2, 2, CV_8UC1, cv::Scalar(255)), &bytes));
  std::ofstream(png, std::ios::binary)
      .write(reinterpret_cast<const char*>(bytes.data()),
             static_cast<std::streamsize>(bytes.size()));
  std::ofstream(text) << "free text\n";
  EXPECT_TRUE(HaveImageReader(png));
  EXPECT_FALSE(HaveImageReader(text));
}

// The point of the module: the runner and the importer start without
// libopencv_imgcodecs and the ~120 libraries it needs.
TEST(ImageCodecs, RunnerAndImporterDoNotLinkOpenCvCodecs) {
  for (const char* tool : {"ag-run", "ag-import", "ag-pipeline"}) {
    const std::string command = std::string("ldd ") + AG_BIN_DIR + "/" + tool;
    FILE* pipe = popen(command.c_str(), "r");
    ASSERT_NE(pipe, nullptr);
    std::string libraries;
    char buffer[4096];
    for (size_t n; (n = fread(buffer, 1, sizeof(buffer), pipe)) > 0;) libraries.append(buffer, n);
    ASSERT_EQ(pclose(pipe), 0) << command;
    EXPECT_NE(libraries.find("libc.so"), std::string::npos) << tool;  // ldd read it
    EXPECT_EQ(libraries.find("libopencv_imgcodecs"), std::string::npos) << tool << ":\n"
                                                                        << libraries;
  }
}

}  // namespace
}  // namespace areagraph::testing

// ImportGridMap hashes the source beside the decode on OpenCV's pool: the
// same grid on one thread and on two, with the digest known or not, and a
// decode error keeps its type.
#include <gtest/gtest.h>

#include <opencv2/imgcodecs.hpp>
#include <random>
#include <vector>

#include "common/error.h"
#include "stages/import/import_stage.h"
#include "store/digest.h"
#include "tests/support/test_support.h"
#include "tests/support/thread_count.h"

namespace areagraph {
namespace {

using testing::ThreadCount;

std::string NoisyPng() {
  std::mt19937 random(3);
  cv::Mat grey(240, 320, CV_8U);
  for (int row = 0; row < grey.rows; ++row) {
    for (int col = 0; col < grey.cols; ++col) grey.at<uint8_t>(row, col) = uint8_t(random());
  }
  std::vector<uchar> png;
  cv::imencode(".png", grey, png);
  return std::string(png.begin(), png.end());
}

TEST(ImportThreads, OneThreadAndTwoGiveTheSameGridAndDigest) {
  testing::TempDir dir;
  const std::string path = dir.File("noisy.png");
  const std::string bytes = NoisyPng();
  testing::WriteFile(path, bytes);
  Sha256 expected;
  expected.Update(bytes);
  std::string one, two, known;
  {
    ThreadCount threads(1);
    one = ImportGridMap(ReadImportSource(path), proto::ImportOptions()).SerializeAsString();
  }
  {
    ThreadCount threads(2);
    const ImportSource source = ReadImportSource(path);
    ASSERT_FALSE(source.HasDigest());
    const proto::GridMap grid = ImportGridMap(source, proto::ImportOptions());
    EXPECT_TRUE(source.HasDigest());
    EXPECT_EQ(grid.source_digest(), expected.FinishHex());
    EXPECT_EQ(ImportInputs(source).digests.at(0), grid.source_digest());
    two = grid.SerializeAsString();
    const ImportSource taken = ReadImportSource(path);
    ImportInputs(taken);  // as ag-run does, before the decode
    known = ImportGridMap(taken, proto::ImportOptions()).SerializeAsString();
  }
  EXPECT_EQ(one, two);
  EXPECT_EQ(one, known);
}

TEST(ImportThreads, ADecodeErrorOnTwoThreadsIsStillAnInputError) {
  testing::TempDir dir;
  const std::string path = dir.File("broken.png");
  std::string bytes = NoisyPng();
  for (size_t i = bytes.size() / 2; i < bytes.size() / 2 + 64; ++i) bytes[i] = char(~bytes[i]);
  testing::WriteFile(path, bytes);
  ThreadCount threads(2);
  EXPECT_THROW(ImportGridMap(ReadImportSource(path), proto::ImportOptions()), InputError);
}

}  // namespace
}  // namespace areagraph

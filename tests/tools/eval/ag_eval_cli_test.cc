// ag-eval as a user runs it: PNG files in, scores out, one line on errors.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <filesystem>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>

#include "tests/support/test_support.h"

namespace areagraph {
namespace {

using testing::CountLines;
using testing::RunTool;
using testing::TempDir;

// An 8-bit label image: zones 1 and 2 split at column `split` of 40.
cv::Mat LabelPng(int split) {
  cv::Mat labels(30, 40, CV_8U, cv::Scalar(2));
  labels.colRange(0, split).setTo(1);
  return labels;
}

// The same partition as a colour image with a white border (background).
cv::Mat ColourPng(int split) {
  cv::Mat bgr(30, 40, CV_8UC3, cv::Scalar(0, 0, 220));
  bgr.colRange(split, 40).setTo(cv::Scalar(30, 200, 30));
  return bgr;
}

TEST(AgEvalCli, IdenticalFilesScoreOne) {
  TempDir dir;
  cv::imwrite(dir.File("result.png"), ColourPng(20));
  cv::imwrite(dir.File("gt.png"), LabelPng(20));
  const auto run =
      RunTool("ag-eval", {"--result", dir.File("result.png"), "--gt", dir.File("gt.png")});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_NE(run.out.find("MCC 1.000"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("precision 1.000"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("recall 1.000"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("gt style labels"), std::string::npos) << run.out;
}

TEST(AgEvalCli, SixteenBitLabelsAndJson) {
  TempDir dir;
  cv::Mat labels16;
  LabelPng(20).convertTo(labels16, CV_16U, 1000);
  cv::imwrite(dir.File("result.png"), labels16);
  cv::imwrite(dir.File("gt.png"), LabelPng(25));
  const auto run = RunTool(
      "ag-eval", {"--result", dir.File("result.png"), "--gt", dir.File("gt.png"), "--json"});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_NE(run.out.find("\"mcc\""), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("\"segments_found\": 2"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("\"gt_style\": \"labels\""), std::string::npos) << run.out;
}

TEST(AgEvalCli, DatasetPrintsATableWithMeanAndMedian) {
  TempDir dir;
  std::filesystem::create_directories(dir.File("results"));
  std::filesystem::create_directories(dir.File("gt"));
  cv::imwrite(dir.File("results/a_seg.png"), LabelPng(20));
  cv::imwrite(dir.File("results/b_seg.png"), LabelPng(25));
  cv::imwrite(dir.File("results/c_seg.png"), LabelPng(25));    // no GT: skipped
  cv::imwrite(dir.File("results/a_other.png"), LabelPng(25));  // wrong suffix: skipped
  cv::imwrite(dir.File("gt/a.png"), LabelPng(20));
  cv::imwrite(dir.File("gt/b.png"), LabelPng(20));
  const auto run = RunTool("ag-eval", {"--dataset", "--results", dir.File("results"), "--gt",
                                       dir.File("gt"), "--suffix", "_seg"});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_NE(run.out.find("| a | 1.000 | 1.000 | 1.000 | 2/2 |"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("| b | 0.775 |"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("| **mean** | **0.887** |"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("| **median** |"), std::string::npos) << run.out;
  EXPECT_EQ(run.out.find("| c |"), std::string::npos) << run.out;
  EXPECT_EQ(CountLines(run.out), 6);
}

// Maps whose result and GT both have kinds get a kind accuracy column; its
// mean is over those maps only.
TEST(AgEvalCli, DatasetWithKindsAddsAKindColumn) {
  TempDir dir;
  std::filesystem::create_directories(dir.File("results"));
  std::filesystem::create_directories(dir.File("gt"));
  for (const char* name : {"a", "b", "c"}) {
    cv::imwrite(dir.File(std::string("results/") + name + ".png"), LabelPng(20));
    cv::imwrite(dir.File(std::string("gt/") + name + ".png"), LabelPng(20));
    testing::WriteFile(dir.File(std::string("gt/") + name + ".kinds.tsv"),
                       "label\tkind\n1\troom\n2\tcorridor\n");
  }
  testing::WriteFile(dir.File("results/a.kinds.tsv"), "label\tkind\n1\troom\n2\tcorridor\n");
  testing::WriteFile(dir.File("results/b.kinds.tsv"), "label\tkind\n1\troom\n2\troom\n");
  const auto run =
      RunTool("ag-eval", {"--dataset", "--results", dir.File("results"), "--gt", dir.File("gt")});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_NE(run.out.find("| kind accuracy |"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("| a | 1.000 | 1.000 | 1.000 | 2/2 | 1.000 |"), std::string::npos)
      << run.out;
  EXPECT_NE(run.out.find("| b | 1.000 | 1.000 | 1.000 | 2/2 | 0.500 |"), std::string::npos)
      << run.out;
  EXPECT_NE(run.out.find("| c | 1.000 | 1.000 | 1.000 | 2/2 | - |"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("| **mean** | **1.000** | 1.000 | 1.000 | 3 maps | 0.750 |"),
            std::string::npos)
      << run.out;
}

TEST(AgEvalCli, MissingFileIsOneLineAndNonZero) {
  TempDir dir;
  cv::imwrite(dir.File("gt.png"), LabelPng(20));
  const auto run =
      RunTool("ag-eval", {"--result", dir.File("missing.png"), "--gt", dir.File("gt.png")});
  EXPECT_NE(run.exit_code, 0);
  EXPECT_EQ(run.signal, 0);
  EXPECT_EQ(CountLines(run.err), 1) << run.err;
  EXPECT_NE(run.err.find("missing.png"), std::string::npos) << run.err;
}

// A FIFO with no writer, as the result, the ground truth or the picture's
// ground truth: refused at once in one line, where cv::imread blocked forever.
TEST(AgEvalCli, FifoInputIsRefusedInsteadOfWaitedFor) {
  TempDir dir;
  cv::imwrite(dir.File("gt.png"), LabelPng(20));
  ASSERT_EQ(::mkfifo(dir.File("fifo.png").c_str(), 0600), 0);
  const std::string bin = testing::BinDir() + "/ag-eval";
  const std::vector<std::vector<std::string>> runs = {
      {"--result", dir.File("fifo.png"), "--gt", dir.File("gt.png")},
      {"--result", dir.File("gt.png"), "--gt", dir.File("fifo.png")},
      {"--gt", dir.File("fifo.png"), "--gt-picture", dir.File("picture.png")},
      {"--gt", dir.File("fifo.png"), "--gt-style", "lines", "--gt-picture",
       dir.File("picture.png")},
  };
  for (const std::vector<std::string>& args : runs) {
    std::vector<std::string> argv = {"timeout", "20", bin};
    argv.insert(argv.end(), args.begin(), args.end());
    const auto run = testing::RunProgram(argv);
    EXPECT_EQ(run.exit_code, 1) << run.err;  // timeout's 124 when it hangs
    EXPECT_EQ(CountLines(run.err), 1) << run.err;
    EXPECT_NE(run.err.find("FIFO"), std::string::npos) << run.err;
  }
}

TEST(AgEvalCli, UnreadableImageIsOneLineAndNonZero) {
  TempDir dir;
  testing::WriteFile(dir.File("result.png"), "not a png");
  cv::imwrite(dir.File("gt.png"), LabelPng(20));
  const auto run =
      RunTool("ag-eval", {"--result", dir.File("result.png"), "--gt", dir.File("gt.png")});
  EXPECT_NE(run.exit_code, 0);
  EXPECT_EQ(CountLines(run.err), 1) << run.err;
}

TEST(AgEvalCli, SizeMismatchIsOneLineAndNonZero) {
  TempDir dir;
  cv::imwrite(dir.File("result.png"), LabelPng(20));
  cv::imwrite(dir.File("gt.png"), cv::Mat(20, 20, CV_8U, cv::Scalar(1)));
  const auto run =
      RunTool("ag-eval", {"--result", dir.File("result.png"), "--gt", dir.File("gt.png")});
  EXPECT_NE(run.exit_code, 0);
  EXPECT_EQ(CountLines(run.err), 1) << run.err;
  EXPECT_NE(run.err.find("40x30"), std::string::npos) << run.err;
}

TEST(AgEvalCli, PaddedGtIsAlignedOrTakesAnOffset) {
  TempDir dir;
  cv::Mat padded(30, 100, CV_8U, cv::Scalar(0));
  LabelPng(20).copyTo(padded.colRange(37, 77));
  cv::imwrite(dir.File("result.png"), LabelPng(20));
  cv::imwrite(dir.File("gt.png"), padded);
  auto run = RunTool("ag-eval", {"--result", dir.File("result.png"), "--gt", dir.File("gt.png")});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_NE(run.out.find("MCC 1.000"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("gt offset 37,0"), std::string::npos) << run.out;
  run = RunTool("ag-eval", {"--result", dir.File("result.png"), "--gt", dir.File("gt.png"),
                            "--gt-offset", "35,0"});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_EQ(run.out.find("MCC 1.000"), std::string::npos) << run.out;
}

// A Bormann-style GT read by default (lines) and with --gt-style override.
TEST(AgEvalCli, GtStyleCanBeForced) {
  TempDir dir;
  cv::Mat grey(30, 40, CV_8U, cv::Scalar(255));
  grey.col(20).setTo(100);  // the door line between two rooms
  cv::imwrite(dir.File("gt.png"), grey);
  cv::imwrite(dir.File("result.png"), LabelPng(20));
  auto run = RunTool("ag-eval", {"--result", dir.File("result.png"), "--gt", dir.File("gt.png")});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_NE(run.out.find("gt style lines"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("MCC 1.000"), std::string::npos) << run.out;
  run = RunTool("ag-eval", {"--result", dir.File("result.png"), "--gt", dir.File("gt.png"),
                            "--gt-style", "labels"});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_NE(run.out.find("gt style labels"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("segments 2/2"), std::string::npos) << run.out;  // grey 100 and 255
}

TEST(AgEvalCli, BadOptionsAreRejected) {
  TempDir dir;
  cv::imwrite(dir.File("result.png"), LabelPng(20));
  auto run = RunTool("ag-eval", {"--result", dir.File("result.png"), "--gt", dir.File("result.png"),
                                 "--gt-style", "stripes"});
  EXPECT_NE(run.exit_code, 0);
  EXPECT_EQ(CountLines(run.err), 1) << run.err;
  run = RunTool("ag-eval", {"--dataset", "--results", dir.File("nowhere"), "--gt", dir.path()});
  EXPECT_NE(run.exit_code, 0);
  EXPECT_NE(run.err.find("nowhere"), std::string::npos) << run.err;
}

}  // namespace
}  // namespace areagraph

// FindRunRegions: the 8-connected regions of a grid's cells over their runs
// are OpenCV's connected components.
#include "stages/clean/cell_runs.h"

#include <gtest/gtest.h>

#include <map>
#include <opencv2/imgproc.hpp>
#include <random>

#include "proto/artifacts.pb.h"
#include "stages/clean/mask_runs.h"

namespace areagraph {
namespace {

// The maximal runs of bytes with a bit of `bit`, byte by byte.
std::vector<std::pair<int, int>> ReferenceRuns(const std::vector<uint8_t>& row, uint8_t bit) {
  std::vector<std::pair<int, int>> runs;
  for (int c = 0; c < int(row.size()); ++c) {
    if ((row[c] & bit) == 0) continue;
    if (!runs.empty() && runs.back().second == c) {
      ++runs.back().second;
    } else {
      runs.push_back({c, c + 1});
    }
  }
  return runs;
}

TEST(ForEachRun, TheMaximalRunsInOrderAcrossWordEdges) {
  // Lengths around multiples of 64 (the word) and 16 (a load); rows of long
  // stretches and of single cells; bytes 0..3 (CellStates) and 0 / 255.
  std::mt19937 random(6);
  for (int trial = 0; trial < 400; ++trial) {
    const int n = trial < 200 ? trial : int(random() % 700);
    const bool mask = trial % 3 == 0;
    std::vector<uint8_t> row(n);
    const int stretch = 1 + int(random() % 80);
    uint8_t value = 0;
    for (int c = 0; c < n; ++c) {
      if (random() % stretch == 0) value = uint8_t(random() % 4);
      row[c] = mask ? (value >= 2 ? 255 : 0) : value;
    }
    for (const uint8_t bit : {uint8_t(1), uint8_t(2), uint8_t(3), uint8_t(0xff)}) {
      std::vector<std::pair<int, int>> runs;
      ForEachRun(row.data(), n, bit, [&](int begin, int end) { runs.push_back({begin, end}); });
      ASSERT_EQ(runs, ReferenceRuns(row, bit)) << "n " << n << ", bit " << int(bit);
    }
  }
}

TEST(CellRuns, RegionsAreOpenCvsEightConnectedComponents) {
  std::mt19937 random(7);
  for (int trial = 0; trial < 100; ++trial) {
    const int width = 1 + int(random() % 90), height = 1 + int(random() % 40);
    std::string cells(size_t(width) * height, char(proto::CELL_FREE));
    const int density = 2 + int(random() % 5);
    for (char& cell : cells) {
      if (random() % density == 0) {
        cell = char(random() % 2 ? proto::CELL_OCCUPIED : proto::CELL_UNKNOWN);
      }
    }
    for (const uint8_t bit : {uint8_t(proto::CELL_OCCUPIED), uint8_t(proto::CELL_UNKNOWN),
                              uint8_t(proto::CELL_OCCUPIED | proto::CELL_UNKNOWN)}) {
      cv::Mat mask(height, width, CV_8U), labels;
      for (int index = 0; index < width * height; ++index) {
        mask.data[index] = (uint8_t(cells[index]) & bit) != 0 ? 255 : 0;
      }
      const int count = cv::connectedComponents(mask, labels, 8, CV_32S);
      const RunRegions found = FindRunRegions(cells, width, height, bit);
      ASSERT_EQ(found.count, count - 1);
      // Every run's cells are the mask's, each region one component.
      std::map<int, int> component_of_region;
      int cells_in_runs = 0;
      for (size_t i = 0; i < found.runs.size(); ++i) {
        const CellRun& run = found.runs[i];
        for (int c = run.begin; c < run.end; ++c) {
          ASSERT_EQ(mask.at<uint8_t>(run.row, c), 255);
          const auto [it, inserted] =
              component_of_region.emplace(found.region[i], labels.at<int>(run.row, c));
          ASSERT_EQ(it->second, labels.at<int>(run.row, c));
          ++cells_in_runs;
        }
        if (i > 0) {
          const CellRun& before = found.runs[i - 1];
          ASSERT_TRUE(before.row < run.row || before.end < run.begin);
        }
      }
      EXPECT_EQ(cells_in_runs, cv::countNonZero(mask));
      EXPECT_EQ(int(component_of_region.size()), count - 1);
    }
  }
}

}  // namespace
}  // namespace areagraph

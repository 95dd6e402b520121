#include "stages/clean/outlier_candidates.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "proto/artifacts.pb.h"
#include "stages/clean/outlier_points.h"
#include "stages/clean/outlier_removal.h"

namespace areagraph {
namespace {

// A free grid with occupied cells at the given positions.
std::string Grid(int width, int height, const std::vector<std::pair<int, int>>& occupied) {
  std::string cells(size_t(width) * height, char(proto::CELL_FREE));
  for (const auto& [col, row] : occupied) cells[row * width + col] = char(proto::CELL_OCCUPIED);
  return cells;
}

TEST(OutlierCandidates, CgalAveragesOverTheQueryPointAndKMore) {
  // On a long line with k = 3, an inner point's four nearest points (itself
  // and three more) are at 0, 1, 1 and 2: score 6 / 4 = 1.5. Were it three
  // points (0, 1, 1) the score would be 2 / 3.
  std::vector<Eigen::Vector2d> line;
  for (int x = 0; x <= 100; ++x) line.emplace_back(x + 0.5, 0.5);
  EXPECT_EQ(FindOutlierPoints(line, 3, 100, 1.49).size(), 101u);
  EXPECT_EQ(FindOutlierPoints(line, 3, 100, 1.51).size(), 2u);  // the two ends
  EXPECT_DOUBLE_EQ(StraightWallScore(4), 1.5);
}

// FindOutlierCandidates against remove_outliers itself over all occupied
// cells: the same cells at or above the threshold.
void ExpectSameAsCgal(const std::string& cells, int width, int height, int k, double threshold) {
  std::vector<int> occupied;
  std::vector<Eigen::Vector2d> centres;
  for (int index = 0; index < width * height; ++index) {
    if (cells[index] != proto::CELL_OCCUPIED) continue;
    occupied.push_back(index);
    centres.emplace_back(index % width + 0.5, index / width + 0.5);
  }
  std::vector<int> expected;
  for (const int point : FindOutlierPoints(centres, k, 100, threshold)) {
    expected.push_back(occupied[point]);
  }
  const double distance = std::sqrt(threshold);
  std::vector<int> found;
  for (const OutlierCandidate& candidate :
       FindOutlierCandidates(OccupiedRows(cells, width, height), k, distance * distance)) {
    found.push_back(candidate.cell);
    EXPECT_GE(candidate.reach2, 0);
  }
  EXPECT_EQ(found, expected) << "k = " << k << ", threshold " << threshold;
}

TEST(OutlierCandidates, AreExactlyTheCellsRemoveOutliersScoresHigh) {
  std::mt19937 random(3);
  for (int trial = 0; trial < 60; ++trial) {
    const int width = 20 + int(random() % 150), height = 20 + int(random() % 150);
    std::vector<std::pair<int, int>> occupied;
    // Sparse specks (some far from everything), a few straight and diagonal
    // walls, a thick block.
    const int specks = int(random() % 40);
    for (int i = 0; i < specks; ++i) {
      occupied.push_back({int(random() % width), int(random() % height)});
    }
    for (int wall = 0; wall < 3; ++wall) {
      const int row = int(random() % height);
      for (int col = 0; col < width * 2 / 3; ++col) occupied.push_back({col, row});
    }
    for (int i = 0; i < std::min(width, height) / 2; ++i) occupied.push_back({i, i});
    for (int row = 5; row < 12; ++row) {
      for (int col = width - 12; col < width - 5; ++col) occupied.push_back({col, row});
    }
    const std::string cells = Grid(width, height, occupied);
    const int k = 2 + int(random() % 30);
    ExpectSameAsCgal(cells, width, height, k, StraightWallScore(k + 1) * (1 + 1e-9));
    ExpectSameAsCgal(cells, width, height, k, 1 + double(random() % 400));
  }
}

TEST(OutlierCandidates, FewerCellsThanNeighboursAverageOverAll) {
  const std::string cells = Grid(50, 40, {{1, 1}, {48, 38}, {20, 20}});
  ExpectSameAsCgal(cells, 50, 40, 18, 10);
}

// A closed room of one-pixel walls in free space, with a short one-pixel stub
// sticking into it from the left wall at row 20, and single specks inside.
std::string RoomWithStub(std::vector<int>* specks) {
  const int width = 60, height = 50;
  std::vector<std::pair<int, int>> occupied;
  for (int col = 5; col <= 54; ++col) {
    occupied.push_back({col, 5});
    occupied.push_back({col, 44});
  }
  for (int row = 5; row <= 44; ++row) {
    occupied.push_back({5, row});
    occupied.push_back({54, row});
  }
  for (int col = 6; col <= 9; ++col) occupied.push_back({col, 20});
  for (const auto& [col, row] : {std::pair{30, 15}, std::pair{40, 35}}) {
    occupied.push_back({col, row});
    specks->push_back(row * width + col);
  }
  return Grid(width, height, occupied);
}

TEST(OutlierRemoval, TakesSpecksButNeverWallsAsDenseAsAStraightOne) {
  // The stub's tip (9, 20) scores 28.1 with k = 18: more than the mean over
  // 18 points of a straight wall (27.2) but less than remove_outliers' own
  // score of a straight wall point (30, over 19 points). It has one free run
  // around it, so only the threshold keeps it. The room's corners score 30.
  // (99 % leaves room for every cell that reaches the threshold.)
  std::vector<int> specks;
  std::string cells = RoomWithStub(&specks);
  const std::string before = cells;
  const std::vector<int> removed = RemoveOutlierCells(cells, 60, 50, 18, 99);
  EXPECT_EQ(removed, specks);
  EXPECT_EQ(cells[20 * 60 + 9], char(proto::CELL_OCCUPIED));
  for (int index = 0; index < 60 * 50; ++index) {
    if (before[index] != cells[index]) {
      EXPECT_TRUE(std::find(specks.begin(), specks.end(), index) != specks.end()) << index;
    }
  }
}

TEST(OutlierRemoval, KeepsThePercentageWithTheHighestScores) {
  // Three specks, farther and farther from the wall: with room for one
  // outlier, the loneliest goes.
  std::vector<std::pair<int, int>> occupied;
  for (int col = 0; col < 100; ++col) occupied.push_back({col, 2});
  occupied.push_back({50, 10});
  occupied.push_back({20, 20});
  occupied.push_back({80, 40});
  std::string cells = Grid(100, 60, occupied);
  // 103 occupied cells; 0.5 % of them leaves room for one. (The wall's ends
  // score high too, but touch the image border, so they would stay.)
  const std::vector<int> removed = RemoveOutlierCells(cells, 100, 60, 18, 0.5);
  EXPECT_EQ(removed, std::vector<int>{40 * 100 + 80});
}

}  // namespace
}  // namespace areagraph

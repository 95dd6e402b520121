// FurniturePiecesByClusters (clusters triangulated alone, outline clusters
// skipped, in parallel) against FurniturePiecesOfWholeShape (one
// triangulation of every point, the definition).
#include "stages/clean/alpha_pieces.h"

#include <gtest/gtest.h>

#include <opencv2/imgproc.hpp>
#include <random>

#include "tests/support/thread_count.h"

namespace areagraph {
namespace {

// Random obstacle blobs (rectangles, dots, lines) on a free grid; their
// 8-connected regions; regions touching the border or picked at random are
// outline, whose cells enter as points with probability `outline_share`.
struct PointSet {
  int width = 0, height = 0;
  cv::Mat labels;
  std::vector<uint8_t> outline;
  std::vector<int> cells;
};

PointSet RandomPoints(std::mt19937& random, int width, int height, int blobs,
                      double outline_share) {
  auto uniform = [&](int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(random); };
  cv::Mat mask(height, width, CV_8U, cv::Scalar(0));
  for (int b = 0; b < blobs; ++b) {
    const int col = uniform(0, width - 1), row = uniform(0, height - 1);
    switch (uniform(0, 3)) {
      case 0:
        mask(cv::Rect(col, row, uniform(1, 9), uniform(1, 9)) & cv::Rect(0, 0, width, height)) =
            255;
        break;
      case 1:
        mask.at<uint8_t>(row, col) = 255;
        break;
      case 2:  // a wall-like line
        mask(cv::Rect(col, row, uniform(10, 60), uniform(1, 2)) & cv::Rect(0, 0, width, height)) =
            255;
        break;
      default:  // points on a circle-ish ring (ties on the grid)
        for (int k = 0; k < 12; ++k) {
          const int c = col + int(std::lround(6 * std::cos(k * M_PI / 6)));
          const int r = row + int(std::lround(6 * std::sin(k * M_PI / 6)));
          if (c >= 0 && r >= 0 && c < width && r < height) mask.at<uint8_t>(r, c) = 255;
        }
    }
  }
  PointSet set;
  set.width = width;
  set.height = height;
  const int count = cv::connectedComponents(mask, set.labels, 8, CV_32S);
  set.outline.assign(count, 0);
  for (int region = 1; region < count; ++region) set.outline[region] = uniform(0, 5) == 0;
  for (int r = 0; r < height; ++r) {
    for (int c = 0; c < width; ++c) {
      if (r == 0 || c == 0 || r == height - 1 || c == width - 1) {
        set.outline[set.labels.at<int>(r, c)] = 1;
      }
    }
  }
  set.outline[0] = 0;
  std::uniform_real_distribution<double> share(0, 1);
  for (int index = 0; index < width * height; ++index) {
    const int region = set.labels.ptr<int>()[index];
    if (region == 0) continue;
    if (!set.outline[region] || share(random) < outline_share) set.cells.push_back(index);
  }
  return set;
}

void ExpectSamePieces(const PointSet& set, double radius, double max_perimeter, int* decided) {
  const int* label = set.labels.ptr<int>();
  const FurniturePieces whole =
      FurniturePiecesOfWholeShape(set.cells, set.width, label, set.outline, radius, max_perimeter);
  FurniturePieces clustered;
  if (!FurniturePiecesByClusters(set.cells, set.width, set.height, label, set.outline, radius,
                                 max_perimeter, &clustered)) {
    return;
  }
  ++*decided;
  ASSERT_EQ(clustered.count, whole.count) << "radius " << radius << " bound " << max_perimeter;
  ASSERT_EQ(clustered.piece_of_point, whole.piece_of_point);
}

TEST(AlphaPieces, ClustersGiveTheWholeShapesPieces) {
  std::mt19937 random(7);
  int decided = 0, furniture = 0, tried = 0;
  for (int round = 0; round < 60; ++round) {
    const int width = 40 + int(random() % 120), height = 40 + int(random() % 120);
    const PointSet set =
        RandomPoints(random, width, height, 10 + int(random() % 80), round % 3 == 0 ? 1.0 : 0.3);
    for (const double radius : {1.0, 1.5, 2.5, 3.0, 6.0}) {
      // Bounds that some pieces' perimeters equal exactly (integers, and
      // 4 + 4 sqrt 2 of a diamond) or come near.
      for (const double bound : {8.0, 12.0, 4 + 4 * std::sqrt(2.0), 20.0, 80.0}) {
        ++tried;
        ExpectSamePieces(set, radius, bound, &decided);
        if (HasFatalFailure()) return;
      }
    }
    furniture +=
        FurniturePiecesOfWholeShape(set.cells, width, set.labels.ptr<int>(), set.outline, 2.5, 20.0)
            .count;
  }
  // Nearly every case is decided without the whole triangulation, and the
  // maps do have furniture.
  EXPECT_GT(decided, tried * 9 / 10);
  EXPECT_GT(furniture, 100);
}

TEST(AlphaPieces, BelowUnitRadiusTheClustersDecline) {
  std::mt19937 random(8);
  const PointSet set = RandomPoints(random, 50, 50, 30, 1.0);
  FurniturePieces pieces;
  EXPECT_FALSE(FurniturePiecesByClusters(set.cells, 50, 50, set.labels.ptr<int>(), set.outline, 0.9,
                                         20.0, &pieces));
}

TEST(AlphaPieces, SameOnOneThreadAndOnTwo) {
  std::mt19937 random(9);
  // Enough points for the parallel path (several thousand).
  const PointSet set = RandomPoints(random, 400, 300, 900, 0.5);
  ASSERT_GT(set.cells.size(), 5000u);
  FurniturePieces one, two;
  bool one_decided = false, two_decided = false;
  {
    testing::ThreadCount threads(1);
    one_decided = FurniturePiecesByClusters(set.cells, 400, 300, set.labels.ptr<int>(), set.outline,
                                            3.0, 40.0, &one);
  }
  {
    testing::ThreadCount threads(2);
    two_decided = FurniturePiecesByClusters(set.cells, 400, 300, set.labels.ptr<int>(), set.outline,
                                            3.0, 40.0, &two);
  }
  ASSERT_TRUE(one_decided);
  ASSERT_TRUE(two_decided);
  EXPECT_EQ(one.count, two.count);
  EXPECT_EQ(one.piece_of_point, two.piece_of_point);
  EXPECT_GT(one.count, 10);
  const FurniturePieces whole =
      FurniturePiecesOfWholeShape(set.cells, 400, set.labels.ptr<int>(), set.outline, 3.0, 40.0);
  EXPECT_EQ(one.piece_of_point, whole.piece_of_point);
}

}  // namespace
}  // namespace areagraph

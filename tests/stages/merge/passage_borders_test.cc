// Passages put on the borders they open.
#include "stages/merge/passage_borders.h"

#include <gtest/gtest.h>

namespace areagraph {
namespace {

// Areas 1 and 3 side by side, kept apart by a wall column, both above area 2.
// Area ids are label - 1.
cv::Mat ThreeAreas() {
  const std::vector<std::string> rows{"11.33", "11.33", "22222"};
  cv::Mat labels(3, 5, CV_32S);
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 5; ++c) labels.at<int>(r, c) = rows[r][c] == '.' ? 0 : rows[r][c] - '0';
  }
  return labels;
}

PassagePlan Passage(int a, int b, double x, double y, double width_px = 2) {
  PassagePlan passage;
  passage.area_a = a;
  passage.area_b = b;
  passage.point = passage.side_a = passage.side_b = {x, y};
  passage.width_px = width_px;
  return passage;
}

const std::vector<int> kLabelOfArea{1, 2, 3};

TEST(PassageBordersTest, EachPassageLiesOnTheBorderBetweenItsAreas) {
  const PlanarPartition partition = BuildPlanarPartition(ThreeAreas(), 3);
  const auto placed = PlacePassagesOnBorders({Passage(0, 1, 1.0, 2.0), Passage(1, 2, 4.0, 2.0)},
                                             partition, kLabelOfArea);
  ASSERT_EQ(placed.size(), 2u);
  for (const PassageOnBorder& p : placed) {
    ASSERT_GE(p.chain, 0);
    const BorderChain& chain = partition.chains[p.chain];
    EXPECT_EQ(std::minmax(chain.left, chain.right),
              std::minmax(p.passage.area_a + 1, p.passage.area_b + 1));
  }
}

TEST(PassageBordersTest, TwoPassagesOnOneBorderAreOneAndTheNarrowerStays) {
  const PlanarPartition partition = BuildPlanarPartition(ThreeAreas(), 3);
  const auto placed = PlacePassagesOnBorders(
      {Passage(0, 1, 0.5, 2.0, 3), Passage(0, 1, 1.5, 2.0, 2)}, partition, kLabelOfArea);
  ASSERT_EQ(placed.size(), 1u);
  EXPECT_EQ(placed[0].passage.width_px, 2);
}

TEST(PassageBordersTest, APassageBetweenAreasThatDoNotTouchIsDroppedWhenOthersJoinThem) {
  const PlanarPartition partition = BuildPlanarPartition(ThreeAreas(), 3);
  const auto placed = PlacePassagesOnBorders(
      {Passage(0, 1, 1.0, 2.0), Passage(1, 2, 4.0, 2.0), Passage(0, 2, 2.5, 2.0)}, partition,
      kLabelOfArea);
  ASSERT_EQ(placed.size(), 2u);
  for (const PassageOnBorder& p : placed) EXPECT_GE(p.chain, 0);
}

TEST(PassageBordersTest, APassageBetweenAreasThatDoNotTouchMovesToTheFreeBorderNearby) {
  // Only 1-2 and 1-3 were found; 1 and 3 do not touch, but the free border
  // 2-3 lies next to the opening and joins them through 2.
  const PlanarPartition partition = BuildPlanarPartition(ThreeAreas(), 3);
  const auto placed = PlacePassagesOnBorders({Passage(0, 1, 1.0, 2.0), Passage(0, 2, 2.5, 2.0)},
                                             partition, kLabelOfArea);
  ASSERT_EQ(placed.size(), 2u);
  ASSERT_GE(placed[1].chain, 0);
  EXPECT_EQ(std::minmax(placed[1].passage.area_a, placed[1].passage.area_b), std::minmax(1, 2));
  EXPECT_EQ(placed[1].passage.area_b, 2);  // the area it kept stays on its side
  // Too far from any free border: it stays where it is, without a border.
  const auto far = PlacePassagesOnBorders({Passage(0, 1, 1.0, 2.0), Passage(0, 2, 2.5, 0.0, 0.5)},
                                          partition, kLabelOfArea);
  ASSERT_EQ(far.size(), 2u);
  EXPECT_EQ(far[1].chain, -1);
  EXPECT_EQ(far[1].passage.area_a, 0);
}

}  // namespace
}  // namespace areagraph

#include "stages/geometry/near_free_mask.h"

#include <gtest/gtest.h>

#include <random>

#include "proto/artifacts.pb.h"
#include "stages/geometry/cell_states.h"

namespace areagraph {
namespace {

TEST(NearFreeMask, AgreesWithTouchesFreeOnRandomGrids) {
  std::mt19937 random(9);
  for (int trial = 0; trial < 50; ++trial) {
    const int width = 1 + int(random() % 40), height = 1 + int(random() % 40);
    std::string cells(size_t(width) * height, char(proto::CELL_UNKNOWN));
    for (char& cell : cells) cell = char(random() % 3);
    const std::vector<uint8_t> mask = NearFreeMask(cells, width, height);
    const CellStates grid(cells, width, height);
    for (int row = 0; row < height; ++row) {
      for (int col = 0; col < width; ++col) {
        const bool expected = grid.IsFree(col, row) || grid.TouchesFree(col, row);
        ASSERT_EQ(bool(mask[grid.Index(col, row)]), expected) << col << "," << row;
      }
    }
  }
}

}  // namespace
}  // namespace areagraph

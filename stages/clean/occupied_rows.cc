#include "stages/clean/occupied_rows.h"

#include <cstdint>
#include <cstring>

#include "proto/artifacts.pb.h"

namespace areagraph {

OccupiedRows::OccupiedRows(const std::string& cells, int width, int height)
    : width_(width), height_(height), row_start_(size_t(height) + 1, 0) {
  for (int row = 0; row < height; ++row) {
    const char* in = cells.data() + size_t(row) * width;
    int col = 0;
    // Eight cells at a time past those without an occupied one: of the
    // states (0, 1, 2) only CELL_OCCUPIED has its lowest bit set.
    static_assert(proto::CELL_OCCUPIED == 1 && proto::CELL_FREE == 0 && proto::CELL_UNKNOWN == 2);
    for (; col + 8 <= width; col += 8) {
      uint64_t eight;
      std::memcpy(&eight, in + col, sizeof(eight));
      if ((eight & 0x0101010101010101u) == 0) continue;
      for (int c = col; c < col + 8; ++c) {
        if (in[c] == proto::CELL_OCCUPIED) cols_.push_back(c);
      }
    }
    for (; col < width; ++col) {
      if (in[col] == proto::CELL_OCCUPIED) cols_.push_back(col);
    }
    row_start_[row + 1] = int(cols_.size());
  }
}

std::vector<int> OccupiedRows::Cells() const {
  std::vector<int> cells;
  cells.reserve(cols_.size());
  for (int row = 0; row < height_; ++row) {
    for (int i = row_start_[row]; i < row_start_[row + 1]; ++i) {
      cells.push_back(row * width_ + cols_[i]);
    }
  }
  return cells;
}

}  // namespace areagraph

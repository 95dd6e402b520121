#include "stages/clean/occupied_rows.h"

#include "proto/artifacts.pb.h"

namespace areagraph {

OccupiedRows::OccupiedRows(const std::string& cells, int width, int height)
    : width_(width), height_(height), row_start_(size_t(height) + 1, 0) {
  for (int row = 0; row < height; ++row) {
    const char* in = cells.data() + size_t(row) * width;
    for (int col = 0; col < width; ++col) {
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

#include "stages/clean/occupied_rows.h"

#include <cstdint>

#include "proto/artifacts.pb.h"
#include "stages/clean/mask_runs.h"

namespace areagraph {

OccupiedRows::OccupiedRows(const std::string& cells, int width, int height)
    : width_(width), height_(height), row_start_(size_t(height) + 1, 0) {
  for (int row = 0; row < height; ++row) {
    const auto* in = reinterpret_cast<const uint8_t*>(cells.data()) + size_t(row) * width;
    // Past runs without an occupied cell eight at a time: of the states
    // (0, 1, 2) only CELL_OCCUPIED has its lowest bit set.
    static_assert(proto::CELL_OCCUPIED == 1 && proto::CELL_FREE == 0 && proto::CELL_UNKNOWN == 2);
    ForEachRun(in, width, 1, [&](int begin, int end) {
      for (int c = begin; c < end; ++c) {
        if (in[c] == proto::CELL_OCCUPIED) cols_.push_back(c);
      }
    });
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

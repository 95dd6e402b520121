#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <string>

#include "proto/artifacts.pb.h"

namespace areagraph {

// Checked, read-only view of a CleanedMap for point queries (ag-prune, ag-cut,
// ag-merge). CellStates is the plain view of any cell string.
class CellGrid {
 public:
  // Throws InputError when the frame's size or
  // resolution does not fit the cells (a corrupt artifact).
  explicit CellGrid(const proto::CleanedMap& map);

  int width() const { return width_; }
  int height() const { return height_; }
  double resolution_m() const { return resolution_m_; }
  bool Contains(int col, int row) const {
    return col >= 0 && row >= 0 && col < width_ && row < height_;
  }
  size_t Index(int col, int row) const { return static_cast<size_t>(row) * width_ + col; }
  proto::CellState At(int col, int row) const {
    return static_cast<proto::CellState>(static_cast<uint8_t>((*cells_)[Index(col, row)]));
  }
  bool IsFree(int col, int row) const {
    return Contains(col, row) && At(col, row) == proto::CELL_FREE;
  }
  // The cell states of one row (0 <= row < height), for whole-grid passes
  // that would otherwise check bounds per cell.
  const uint8_t* CellRow(int row) const {
    return reinterpret_cast<const uint8_t*>(cells_->data()) + Index(0, row);
  }
  // Whether the cell under a point in pixel coordinates is free; nothing
  // outside the map is.
  bool FreeAt(const Eigen::Vector2d& point) const;

 private:
  int width_ = 0;
  int height_ = 0;
  double resolution_m_ = 0;
  const std::string* cells_;
};

}  // namespace areagraph

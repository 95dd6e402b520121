#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <string>

#include "proto/artifacts.pb.h"

namespace areagraph {

// The raw CellState bytes of a GridMap or CleanedMap (width * height, row-major
// from the top row) with the neighbour tests the cleaning and site code needs.
// Cells outside the image read as unknown, so the image border behaves like
// unexplored space. (CellGrid is the checked view of a CleanedMap for point
// queries; this one works on any cell string, also while it is being edited.)
class CellStates {
 public:
  CellStates(const std::string& cells, int width, int height)
      : cells_(&cells), width_(width), height_(height) {}

  int width() const { return width_; }
  int height() const { return height_; }
  int Index(int col, int row) const { return row * width_ + col; }
  bool Contains(int col, int row) const {
    return col >= 0 && row >= 0 && col < width_ && row < height_;
  }
  proto::CellState At(int col, int row) const {
    if (!Contains(col, row)) return proto::CELL_UNKNOWN;
    return static_cast<proto::CellState>(static_cast<uint8_t>((*cells_)[Index(col, row)]));
  }
  bool IsFree(int col, int row) const { return At(col, row) == proto::CELL_FREE; }
  // True when one of the 8 neighbours of (col, row) is free.
  bool TouchesFree(int col, int row) const;

 private:
  const std::string* cells_;
  int width_;
  int height_;
};

// Centre of cell (col, row) in pixel coordinates.
inline Eigen::Vector2d CellCentre(int col, int row) { return {col + 0.5, row + 0.5}; }

// Throws InputError unless the frame has a positive size and `cells` holds
// width * height valid CellState bytes.
void CheckCellStates(const std::string& cells, int width, int height);

}  // namespace areagraph

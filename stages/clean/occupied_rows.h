#pragma once

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace areagraph {

// The occupied cells of a CellState grid, row by row with increasing
// columns, for finding the occupied cells near a point without visiting the
// empty cells in between.
class OccupiedRows {
 public:
  OccupiedRows(const std::string& cells, int width, int height);

  int width() const { return width_; }
  int height() const { return height_; }
  // Number of occupied cells.
  int count() const { return int(cols_.size()); }
  // The occupied cells in row-major order, as flat indices.
  std::vector<int> Cells() const;

  // Calls visit(flat index, squared distance) for every occupied cell within
  // squared distance `radius2` of cell (col, row), itself included.
  template <typename Visit>
  void ForEachWithin(int col, int row, long radius2, Visit&& visit) const {
    const long reach = long(std::sqrt(double(radius2)));
    const long first_row = std::max(0L, row - reach);
    const long last_row = std::min<long>(height_ - 1, row + reach);
    for (long r = first_row; r <= last_row; ++r) {
      const long dr2 = (r - row) * (r - row);
      const long span = long(std::sqrt(double(radius2 - dr2)));
      const auto begin = cols_.begin() + row_start_[r];
      const auto end = cols_.begin() + row_start_[r + 1];
      for (auto c = std::lower_bound(begin, end, int(col - span)); c != end && *c <= col + span;
           ++c) {
        const long d2 = dr2 + long(*c - col) * (*c - col);
        if (d2 <= radius2) visit(int(r * width_ + *c), d2);
      }
    }
  }

 private:
  int width_;
  int height_;
  // Cells of row r are cols_[row_start_[r] .. row_start_[r + 1]).
  std::vector<int> row_start_;
  std::vector<int> cols_;
};

}  // namespace areagraph

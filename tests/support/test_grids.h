#pragma once

#include <string>

#include "proto/artifacts.pb.h"
#include "proto/pipeline_options.pb.h"

namespace areagraph::testing {

// A grid map drawn with rectangles, for the clean and Voronoi tests.
class TestGrid {
 public:
  TestGrid(int width, int height, proto::CellState fill = proto::CELL_FREE)
      : width_(width), height_(height), cells_(size_t(width) * height, char(fill)) {}

  // Fills columns [col0, col1] x rows [row0, row1] (inclusive).
  TestGrid& Fill(int col0, int row0, int col1, int row1, proto::CellState state) {
    for (int row = row0; row <= row1; ++row) {
      for (int col = col0; col <= col1; ++col) cells_[Index(col, row)] = char(state);
    }
    return *this;
  }
  // A closed rectangular wall `thickness` cells thick whose outer corners are
  // (col0, row0) and (col1, row1).
  TestGrid& Walls(int col0, int row0, int col1, int row1, int thickness) {
    const int t = thickness - 1;
    Fill(col0, row0, col1, row0 + t, proto::CELL_OCCUPIED);
    Fill(col0, row1 - t, col1, row1, proto::CELL_OCCUPIED);
    Fill(col0, row0, col0 + t, row1, proto::CELL_OCCUPIED);
    Fill(col1 - t, row0, col1, row1, proto::CELL_OCCUPIED);
    return *this;
  }

  int Index(int col, int row) const { return row * width_ + col; }
  proto::CellState At(int col, int row) const { return proto::CellState(cells_[Index(col, row)]); }
  const std::string& cells() const { return cells_; }
  int width() const { return width_; }
  int height() const { return height_; }

  proto::GridMap ToGridMap(double resolution_m = 0.05) const {
    proto::GridMap map;
    map.set_format_version(1);
    map.mutable_frame()->set_resolution_m(resolution_m);
    map.mutable_frame()->set_width_px(width_);
    map.mutable_frame()->set_height_px(height_);
    map.set_cells(cells_);
    return map;
  }
  proto::CleanedMap ToCleanedMap(double resolution_m = 0.05) const {
    proto::CleanedMap map;
    map.set_format_version(1);
    *map.mutable_frame() = ToGridMap(resolution_m).frame();
    map.set_cells(cells_);
    // As ag-clean writes it with the default options.
    map.set_robot_width_m(proto::CleanOptions().robot_width_m());
    return map;
  }

 private:
  int width_;
  int height_;
  std::string cells_;
};

}  // namespace areagraph::testing

#include "stages/geometry/cell_states.h"

#include <algorithm>

#include "common/error.h"

namespace areagraph {

bool CellStates::TouchesFree(int col, int row) const {
  for (int dr = -1; dr <= 1; ++dr) {
    for (int dc = -1; dc <= 1; ++dc) {
      if ((dr != 0 || dc != 0) && IsFree(col + dc, row + dr)) return true;
    }
  }
  return false;
}

void CheckCellStates(const std::string& cells, int width, int height) {
  if (width <= 0 || height <= 0) {
    throw InputError("the map has an empty frame (" + std::to_string(width) + "x" +
                     std::to_string(height) + " pixels)");
  }
  if (cells.size() != static_cast<size_t>(width) * static_cast<size_t>(height)) {
    throw InputError("the map has " + std::to_string(cells.size()) + " cells but its frame is " +
                     std::to_string(width) + "x" + std::to_string(height));
  }
  // While the valid states are 0..CellState_MAX, one pass for the largest
  // byte (which vectorises) replaces a look-up per cell.
  static const bool contiguous = [] {
    for (int value = 0; value <= proto::CellState_MAX; ++value) {
      if (!proto::CellState_IsValid(value)) return false;
    }
    return true;
  }();
  uint8_t largest = 0;
  for (const char cell : cells) largest = std::max(largest, static_cast<uint8_t>(cell));
  if (!contiguous || largest > proto::CellState_MAX) {
    for (const char cell : cells) {
      if (!proto::CellState_IsValid(static_cast<uint8_t>(cell))) {
        throw InputError("the map has an invalid cell value " +
                         std::to_string(static_cast<uint8_t>(cell)));
      }
    }
  }
}

}  // namespace areagraph

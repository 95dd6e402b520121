#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace areagraph {

// For every cell of a CellState grid (width * height bytes, row-major): 1
// when the cell itself or one of its 8 neighbours is free, else 0. For a
// non-free cell that is CellStates::TouchesFree, for the whole grid in two
// passes of byte operations instead of 8 bounds-checked look-ups per cell.
// Cells outside the image count as unknown, never free.
std::vector<uint8_t> NearFreeMask(const std::string& cells, int width, int height);

}  // namespace areagraph

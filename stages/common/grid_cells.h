#pragma once

#include <cstdint>
#include <string>

namespace areagraph {

// How many cells of each CellState a grid holds.
struct CellCounts {
  int64_t free = 0;
  int64_t occupied = 0;
  int64_t unknown = 0;
};

// Counts the cells of a GridMap/CleanedMap `cells` byte string.
CellCounts CountCells(const std::string& cells);

}  // namespace areagraph

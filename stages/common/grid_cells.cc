#include "stages/common/grid_cells.h"

#include "proto/artifacts.pb.h"

namespace areagraph {

CellCounts CountCells(const std::string& cells) {
  CellCounts counts;
  for (const char cell : cells) {
    switch (static_cast<uint8_t>(cell)) {
      case proto::CELL_FREE:
        ++counts.free;
        break;
      case proto::CELL_OCCUPIED:
        ++counts.occupied;
        break;
      default:
        ++counts.unknown;
        break;
    }
  }
  return counts;
}

}  // namespace areagraph

#include "stages/geometry/cell_grid.h"

#include <cmath>

#include "common/error.h"
#include "stages/geometry/cell_states.h"

namespace areagraph {

CellGrid::CellGrid(const proto::CleanedMap& map)
    : width_(map.frame().width_px()),
      height_(map.frame().height_px()),
      resolution_m_(map.frame().resolution_m()),
      cells_(&map.cells()) {
  CheckCellStates(map.cells(), width_, height_);
  if (!(resolution_m_ > 0) || !std::isfinite(resolution_m_)) {
    throw InputError("the map has no valid resolution (" + std::to_string(resolution_m_) +
                     " m per pixel)");
  }
}

bool CellGrid::FreeAt(const Eigen::Vector2d& point) const {
  // Also rejects NaN, and keeps the casts below in range.
  if (!(point.x() >= 0 && point.y() >= 0 && point.x() < width_ && point.y() < height_)) {
    return false;
  }
  return IsFree(static_cast<int>(point.x()), static_cast<int>(point.y()));
}

}  // namespace areagraph

#include "stages/clean/clean_stage.h"

#include <algorithm>

#include "common/error.h"
#include "stages/clean/clean_parameters.h"
#include "stages/clean/furniture_removal.h"
#include "stages/clean/outlier_removal.h"
#include "stages/clean/unknown_islands.h"
#include "stages/common/stage_info.h"
#include "stages/geometry/cell_states.h"

namespace areagraph {

proto::CleanedMap CleanGridMap(const proto::GridMap& map, const proto::CleanOptions& options) {
  const int width = map.frame().width_px();
  const int height = map.frame().height_px();
  CheckCellStates(map.cells(), width, height);
  const CleanParameters parameters = CleanParametersFor(options, map.frame());
  const auto free_cells = std::count(map.cells().begin(), map.cells().end(), proto::CELL_FREE);
  if (free_cells == 0) throw InputError("the map has no free space");
  if (free_cells == static_cast<long>(map.cells().size())) {
    throw InputError("the map has no obstacle cells");
  }

  std::string cells = map.cells();
  std::vector<int> islands =
      FreeUnknownIslands(cells, width, height, parameters.unknown_island_max_cells);
  const std::vector<int> outliers = RemoveOutlierCells(
      cells, width, height, parameters.outlier_neighbors, parameters.outlier_percent);
  const FurnitureRemoval furniture = RemoveFurniture(
      cells, width, height, parameters.alpha_radius_px, parameters.furniture_max_perimeter_px,
      parameters.keep_wall_pieces ? &parameters.wall_pieces : nullptr);

  proto::CleanedMap cleaned;
  cleaned.set_format_version(kCleanedMapFormatVersion);
  *cleaned.mutable_frame() = map.frame();
  cleaned.set_cells(std::move(cells));
  cleaned.mutable_removed_outlier_cells()->Add(outliers.begin(), outliers.end());
  // Both lists are increasing.
  const auto middle =
      islands.insert(islands.end(), furniture.removed_cells.begin(), furniture.removed_cells.end());
  std::inplace_merge(islands.begin(), middle, islands.end());
  cleaned.mutable_removed_furniture_cells()->Add(islands.begin(), islands.end());
  for (const proto::Polygon& shape : furniture.shapes) *cleaned.add_furniture_shapes() = shape;
  return cleaned;
}

}  // namespace areagraph

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
  // Whether there is a free cell and a non-free one: both are found early.
  const std::string& states = map.cells();
  if (std::find(states.begin(), states.end(), char(proto::CELL_FREE)) == states.end()) {
    throw InputError("the map has no free space");
  }
  if (std::find_if(states.begin(), states.end(),
                   [](char state) { return state != char(proto::CELL_FREE); }) == states.end()) {
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
  cleaned.set_robot_width_m(options.robot_width_m());
  return cleaned;
}

}  // namespace areagraph

#include "stages/clean/clean_parameters.h"

#include <algorithm>
#include <cmath>

#include "common/error.h"
#include "common/text.h"
#include "stages/common/pipeline_options_check.h"
#include "stages/common/skipped_passes.h"
#include "stages/geometry/furniture_shape.h"
#include "stages/geometry/wall_thickness.h"

namespace areagraph {

CleanParameters CleanParametersFor(const proto::CleanOptions& options,
                                   const proto::MapFrame& frame) {
  CheckCleanOptions(options);
  const double resolution = frame.resolution_m();
  if (!std::isfinite(resolution) || resolution <= 0) {
    throw InputError("the map's resolution " + FormatNumber(resolution) +
                     " m/pixel is not a positive number");
  }
  const double robot_width = options.robot_width_m();
  const double map_extent_m = std::max(frame.width_px(), frame.height_px()) * resolution;
  if (robot_width >= map_extent_m) {
    throw OptionsError("clean.robot_width_m = " + FormatNumber(robot_width) +
                       " is not smaller than the map (" + FormatNumber(map_extent_m) + " m)");
  }
  CleanParameters parameters;
  parameters.outlier_neighbors = options.outlier_neighbors();
  parameters.outlier_percent = options.outlier_percent();
  parameters.alpha_radius_px = robot_width / (2 * resolution);
  parameters.furniture_max_perimeter_px = options.furniture_max_perimeter_m() / resolution;
  parameters.unknown_island_max_cells = options.unknown_island_max_m2() / (resolution * resolution);
  parameters.keep_wall_pieces = RunsStagePass(options, proto::CleanOptions::KEEP_WALL_PIECES);
  parameters.wall_pieces.thinner_than_px = kMinFurnitureThicknessM / resolution;
  parameters.wall_pieces.min_length_px = kMinWallPieceM / resolution;
  parameters.wall_pieces.max_gap_px = kWallPieceGapM / resolution;
  parameters.wall_pieces.max_wall_px = kMaxWallThicknessM / resolution;
  return parameters;
}

}  // namespace areagraph

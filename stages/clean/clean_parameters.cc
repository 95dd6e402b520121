#include "stages/clean/clean_parameters.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "store/error.h"

namespace areagraph {
namespace {

std::string Number(double value) {
  std::ostringstream out;
  out << value;
  return out.str();
}

}  // namespace

CleanParameters CheckCleanOptions(const proto::CleanOptions& options,
                                  const proto::MapFrame& frame) {
  const double resolution = frame.resolution_m();
  if (!std::isfinite(resolution) || resolution <= 0) {
    throw InputError("the map's resolution " + Number(resolution) +
                     " m/pixel is not a positive number");
  }
  CleanParameters parameters;
  parameters.outlier_neighbors = options.outlier_neighbors();
  if (parameters.outlier_neighbors < 2 || parameters.outlier_neighbors > 1000) {
    throw OptionsError("clean.outlier_neighbors must be between 2 and 1000 (got " +
                       std::to_string(parameters.outlier_neighbors) + ")");
  }
  parameters.outlier_percent = options.outlier_percent();
  if (!std::isfinite(parameters.outlier_percent) || parameters.outlier_percent < 0 ||
      parameters.outlier_percent >= 100) {
    throw OptionsError("clean.outlier_percent must be at least 0 and below 100 (got " +
                       Number(parameters.outlier_percent) + ")");
  }
  const double robot_width = options.robot_width_m();
  if (!std::isfinite(robot_width) || robot_width <= 0) {
    throw OptionsError("clean.robot_width_m must be a positive number of metres (got " +
                       Number(robot_width) + ")");
  }
  const double map_extent_m = std::max(frame.width_px(), frame.height_px()) * resolution;
  if (robot_width >= map_extent_m) {
    throw OptionsError("clean.robot_width_m = " + Number(robot_width) +
                       " is not smaller than the map (" + Number(map_extent_m) + " m)");
  }
  parameters.alpha_radius_px = robot_width / (2 * resolution);
  const double max_perimeter = options.furniture_max_perimeter_m();
  if (!std::isfinite(max_perimeter) || max_perimeter < 0) {
    throw OptionsError("clean.furniture_max_perimeter_m must be a number of metres >= 0 (got " +
                       Number(max_perimeter) + ")");
  }
  parameters.furniture_max_perimeter_px = max_perimeter / resolution;
  const double island_m2 = options.unknown_island_max_m2();
  if (!std::isfinite(island_m2) || island_m2 < 0) {
    throw OptionsError("clean.unknown_island_max_m2 must be a number of square metres >= 0 (got " +
                       Number(island_m2) + ")");
  }
  parameters.unknown_island_max_cells = island_m2 / (resolution * resolution);
  return parameters;
}

}  // namespace areagraph

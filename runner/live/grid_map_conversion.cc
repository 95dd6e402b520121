// GridMap <-> grid_map_t (declared in lcm_conversion.h). The LCM type follows
// ROS: row 0 at the origin (bottom) and cell values -1 / 0..100; GridMap has
// row 0 at the top and CellState bytes.
#include <cmath>
#include <sstream>

#include "common/error.h"
#include "common/map_name.h"
#include "runner/live/lcm_conversion.h"
#include "stages/common/pipeline_options_check.h"
#include "stages/import/import_stage.h"
#include "stages/import/map_yaml.h"

namespace areagraph {
namespace {

int8_t ToLcmCell(char state) {
  switch (static_cast<proto::CellState>(state)) {
    case proto::CELL_FREE:
      return kLcmFreeCell;
    case proto::CELL_OCCUPIED:
      return kLcmOccupiedCell;
    default:
      return kLcmUnknownCell;
  }
}

// map_saver's classification; -2 for values ROS does not define.
int FromLcmCell(int8_t value) {
  if (value == kLcmUnknownCell) return proto::CELL_UNKNOWN;
  if (value < 0 || value > 100) return -2;
  if (value <= kLcmFreeMaxPercent) return proto::CELL_FREE;
  if (value >= kLcmOccupiedMinPercent) return proto::CELL_OCCUPIED;
  return proto::CELL_UNKNOWN;
}

[[noreturn]] void Reject(const std::string& name, const std::string& what) {
  throw InputError("grid_map_t '" + name + "': " + what);
}

}  // namespace

areagraph_lcm::grid_map_t ToLcmGridMap(const std::string& map_name, int64_t utime,
                                       const proto::GridMap& grid) {
  areagraph_lcm::grid_map_t out;
  out.utime = utime;
  out.name = map_name;
  const proto::MapFrame& frame = grid.frame();
  out.resolution_m = frame.resolution_m();
  out.origin_x_m = frame.origin_x_m();
  out.origin_y_m = frame.origin_y_m();
  out.origin_yaw_rad = frame.origin_yaw_rad();
  out.width = frame.width_px();
  out.height = frame.height_px();
  const int64_t width = out.width;
  out.cells.resize(grid.cells().size());
  for (int64_t row = 0; row < out.height; ++row) {
    const int64_t from = (out.height - 1 - row) * width;
    for (int64_t col = 0; col < width; ++col) {
      out.cells[row * width + col] = ToLcmCell(grid.cells()[from + col]);
    }
  }
  out.num_cells = static_cast<int32_t>(out.cells.size());
  return out;
}

proto::GridMap GridMapFromLcm(const areagraph_lcm::grid_map_t& message, int64_t max_cells) {
  try {
    CheckMapName(message.name);
  } catch (const InputError& error) {
    throw InputError(std::string("grid_map_t: ") + error.what());
  }
  const std::string& name = message.name;
  try {
    CheckResolution(message.resolution_m, "resolution_m", /*is_option=*/false);
  } catch (const InputError& error) {
    Reject(name, error.what());
  }
  const std::string origin =
      OriginProblem(message.origin_x_m, message.origin_y_m, message.origin_yaw_rad);
  if (!origin.empty()) Reject(name, origin);
  if (message.width <= 0 || message.height <= 0) {
    Reject(name, "size " + std::to_string(message.width) + "x" + std::to_string(message.height) +
                     " is not positive");
  }
  const int64_t width = message.width;
  const int64_t height = message.height;
  if (width * height > max_cells) {
    Reject(name, std::to_string(width) + "x" + std::to_string(height) +
                     " cells exceed the limit of " + std::to_string(max_cells) +
                     " (import.max_pixels)");
  }
  if (message.num_cells != width * height ||
      static_cast<int64_t>(message.cells.size()) != width * height) {
    Reject(name, "has " + std::to_string(message.cells.size()) + " cells (num_cells " +
                     std::to_string(message.num_cells) + ") but width * height is " +
                     std::to_string(width * height));
  }

  proto::GridMap grid;
  grid.set_format_version(kGridMapFormatVersion);
  proto::MapFrame* frame = grid.mutable_frame();
  frame->set_resolution_m(message.resolution_m);
  frame->set_origin_x_m(message.origin_x_m);
  frame->set_origin_y_m(message.origin_y_m);
  frame->set_origin_yaw_rad(message.origin_yaw_rad);
  frame->set_width_px(message.width);
  frame->set_height_px(message.height);
  std::string cells(message.cells.size(), '\0');
  for (int64_t row = 0; row < height; ++row) {
    const int64_t to = (height - 1 - row) * width;
    for (int64_t col = 0; col < width; ++col) {
      const int8_t value = message.cells[row * width + col];
      const int state = FromLcmCell(value);
      if (state < 0) {
        Reject(name, "cell (" + std::to_string(col) + ", " + std::to_string(row) + ") has value " +
                         std::to_string(value) + "; valid are -1 (unknown) and 0..100");
      }
      cells[to + col] = static_cast<char>(state);
    }
  }
  grid.set_cells(std::move(cells));
  return grid;
}

}  // namespace areagraph

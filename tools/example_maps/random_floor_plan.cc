#include "tools/example_maps/random_floor_plan.h"

#include <random>
#include <vector>

namespace areagraph::floorplan {

FloorPlan RandomOfficePlan(uint32_t seed) {
  std::mt19937 random(seed);
  auto uniform = [&](double low, double high) {
    return std::uniform_real_distribution<double>(low, high)(random);
  };
  auto count = [&](int low, int high) {
    return std::uniform_int_distribution<int>(low, high)(random);
  };

  // Room widths along the corridor, the same split on both sides.
  std::vector<double> widths;
  for (int i = count(2, 4); i > 0; --i) widths.push_back(uniform(3.0, 5.0));
  double length = 0;
  for (double width : widths) length += width;
  const double corridor = uniform(1.5, 2.5);
  const double depth_top = uniform(3.0, 4.5), depth_bottom = uniform(3.0, 4.5);
  const double margin = 1.0;
  FloorPlan plan(length + 2 * margin, depth_top + corridor + depth_bottom + 2 * margin);

  const double corridor_y = margin + depth_top;
  DrawRoom(plan, {margin, corridor_y, length, corridor});
  double x = margin;
  for (double width : widths) {
    DrawRoom(plan, {x, margin, width, depth_top});
    DrawRoom(plan, {x, corridor_y + corridor, width, depth_bottom});
    x += width;
  }
  x = margin;
  for (double width : widths) {
    DrawDoor(plan, x + uniform(0.9, width - 0.9), corridor_y, uniform(0.8, 1.1),
             WallDirection::kHorizontal);
    DrawDoor(plan, x + uniform(0.9, width - 0.9), corridor_y + corridor, uniform(0.8, 1.1),
             WallDirection::kHorizontal);
    // A desk against each room's outer wall keeps the doorway clear.
    DrawFurniture(plan, {x + uniform(0.4, width - 2.0), margin + 0.3, 1.4, 0.6});
    DrawFurniture(plan, {x + uniform(0.4, width - 2.0), corridor_y + corridor + depth_bottom - 0.9,
                         1.4, 0.6});
    x += width;
  }
  DrawNoiseDots(plan, count(5, 30), seed);
  return plan;
}

FloorPlan ClutteredRoomPlan(int size_px, double percent, uint32_t seed) {
  const double size_m = size_px * 0.05;
  FloorPlan plan(size_m, size_m);
  DrawRoom(plan, {0, 0, size_m, size_m});
  const int free_cells = cv::countNonZero(plan.image() == kFreeGrey);
  DrawNoiseDots(plan, static_cast<int>(free_cells * percent / 100), seed);
  return plan;
}

}  // namespace areagraph::floorplan

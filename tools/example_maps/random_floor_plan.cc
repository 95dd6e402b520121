#include "tools/example_maps/random_floor_plan.h"

#include <algorithm>
#include <random>
#include <utility>
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

FloorPlan LargeOfficePlan(double width_m, double height_m, uint32_t seed, FloorPlan* rooms_closed) {
  std::mt19937 random(seed);
  // mt19937's sequence is the same everywhere; the distributions are not.
  auto uniform = [&](double low, double high) {
    return low + (high - low) * ((random() >> 8) * (1.0 / 16777216.0));
  };
  constexpr double kMargin = 1.0, kCorridor = 2.0, kDepth = 5.0;
  const double block = 2 * kDepth + kCorridor;
  const int blocks = std::max(1, static_cast<int>((height_m - 2 * kMargin) / block));
  const double right = width_m - kMargin, left = kMargin + kCorridor;
  FloorPlan plan(width_m, height_m);
  FloorPlan closed(width_m, height_m);

  // The corridors, one walled region: the spine and its branches.
  std::vector<RectM> corridors = {{kMargin, kMargin, kCorridor, blocks * block}};
  for (int b = 0; b < blocks; ++b) {
    corridors.push_back({left - 0.5, kMargin + b * block + kDepth, right - left + 0.5, kCorridor});
  }
  DrawRegion(plan, corridors);
  // Without doors, the spine and each branch are regions of their own.
  DrawRoom(closed, corridors[0]);
  for (size_t i = 1; i < corridors.size(); ++i) {
    DrawRoom(closed, {left, corridors[i].y, right - left, kCorridor});
  }
  std::vector<std::pair<RectM, bool>> rooms;  // room, whether its door is on its bottom wall
  for (int b = 0; b < blocks; ++b) {
    const double top = kMargin + b * block;
    for (const bool above : {true, false}) {
      for (double x = left; right - x >= 3.0;) {
        double width = uniform(3.0, 7.0);
        if (right - x - width < 3.0) width = right - x;
        rooms.push_back({{x, above ? top : top + kDepth + kCorridor, width, kDepth}, above});
        x += width;
      }
    }
  }
  for (const auto& [room, above] : rooms) {
    DrawRoom(plan, room);
    DrawRoom(closed, room);
  }
  for (const auto& [room, above] : rooms) {
    DrawDoor(plan, room.x + uniform(0.9, room.width - 0.9), above ? room.y + kDepth : room.y,
             uniform(0.8, 1.1), WallDirection::kHorizontal);
    if (uniform(0, 1) < 0.7) {
      const RectM desk{room.x + uniform(0.4, room.width - 2.0),
                       above ? room.y + 0.3 : room.y + kDepth - 0.9, 1.4, 0.6};
      DrawFurniture(plan, desk);
      DrawFurniture(closed, desk);
    }
  }
  DrawNoiseDots(plan, static_cast<int>(width_m * height_m / 50), seed);
  if (rooms_closed != nullptr) *rooms_closed = closed;
  return plan;
}

}  // namespace areagraph::floorplan

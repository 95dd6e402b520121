#include "tools/bench/grid_geodesic.h"

#include <cmath>
#include <cstdlib>
#include <functional>
#include <limits>
#include <opencv2/imgproc.hpp>
#include <queue>
#include <utility>

namespace areagraph {
namespace {

constexpr int kSteps[8][2] = {{1, 0}, {-1, 0}, {0, 1}, {0, -1}, {1, 1}, {1, -1}, {-1, 1}, {-1, -1}};

}  // namespace

GridGeodesic::GridGeodesic(const proto::GridMap& grid, const GridPathRules& rules)
    : width_(grid.frame().width_px()),
      height_(grid.frame().height_px()),
      resolution_m_(grid.frame().resolution_m()),
      no_corner_cutting_(rules.no_corner_cutting) {
  const size_t cells = static_cast<size_t>(width_) * height_;
  free_.resize(cells);
  for (size_t i = 0; i < cells; ++i) free_[i] = grid.cells()[i] == proto::CELL_FREE;
  if (rules.clearance_m > 0) {
    // Distance from each cell's centre to the nearest blocked cell's edge.
    cv::Mat open(height_, width_, CV_8U);
    for (size_t i = 0; i < cells; ++i) open.data[i] = free_[i] ? 255 : 0;
    cv::Mat distance;
    cv::distanceTransform(open, distance, cv::DIST_L2, cv::DIST_MASK_PRECISE);
    for (size_t i = 0; i < cells; ++i) {
      if ((distance.at<float>(static_cast<int>(i)) - 0.5) * resolution_m_ < rules.clearance_m) {
        free_[i] = 0;
      }
    }
  }
  component_.assign(cells, -1);
  best_.resize(cells);
  stamp_.assign(cells, 0);
  int components = 0;
  std::vector<int> stack;
  for (size_t seed = 0; seed < cells; ++seed) {
    if (!free_[seed] || component_[seed] >= 0) continue;
    component_[seed] = components;
    stack.push_back(static_cast<int>(seed));
    while (!stack.empty()) {
      const int cell = stack.back();
      stack.pop_back();
      for (const auto& step : kSteps) {
        const int next = StepFrom(cell, step[0], step[1]);
        if (next >= 0 && component_[next] < 0) {
          component_[next] = components;
          stack.push_back(next);
        }
      }
    }
    ++components;
  }
}

int GridGeodesic::StepFrom(int cell, int dx, int dy) const {
  const int x = cell % width_ + dx, y = cell / width_ + dy;
  if (x < 0 || y < 0 || x >= width_ || y >= height_) return -1;
  const int next = y * width_ + x;
  if (!free_[next]) return -1;
  if (no_corner_cutting_ && dx != 0 && dy != 0 &&
      (!free_[cell + dx] || !free_[cell + dy * width_])) {
    return -1;
  }
  return next;
}

double GridGeodesic::Length(int from, int to, bool estimate) {
  const double infinity = std::numeric_limits<double>::infinity();
  if (!free_[from] || !free_[to] || component_[from] != component_[to]) return infinity;
  ++search_;
  const int goal_x = to % width_, goal_y = to / width_;
  auto octile = [&](int cell) {
    if (!estimate) return 0.0;
    const int dx = std::abs(cell % width_ - goal_x), dy = std::abs(cell / width_ - goal_y);
    return (std::max(dx, dy) + (std::sqrt(2.0) - 1) * std::min(dx, dy)) * resolution_m_;
  };
  using Entry = std::pair<double, int>;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<>> open;
  stamp_[from] = search_;
  best_[from] = 0;
  open.emplace(octile(from), from);
  while (!open.empty()) {
    const auto [priority, cell] = open.top();
    open.pop();
    if (cell == to) return best_[cell];
    if (priority > best_[cell] + octile(cell) + 1e-12) continue;  // stale entry
    for (const auto& step : kSteps) {
      const int next = StepFrom(cell, step[0], step[1]);
      if (next < 0) continue;
      const double length =
          best_[cell] + (step[0] != 0 && step[1] != 0 ? std::sqrt(2.0) : 1.0) * resolution_m_;
      if (stamp_[next] != search_ || length < best_[next]) {
        stamp_[next] = search_;
        best_[next] = length;
        open.emplace(length + octile(next), next);
      }
    }
  }
  return infinity;
}

}  // namespace areagraph

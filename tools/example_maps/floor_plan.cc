#include "tools/example_maps/floor_plan.h"

#include <algorithm>
#include <cmath>
#include <random>
#include <sstream>
#include <stdexcept>

#include "stages/common/png_file.h"

namespace areagraph::floorplan {
namespace {

// std::uniform_int_distribution differs between standard libraries, the
// mt19937 sequence does not: this keeps drawings identical everywhere.
uint32_t UniformIndex(std::mt19937& random, uint32_t count) { return random() % count; }

// Pixel rectangle [x0, x1) x [y0, y1), clipped to the image.
cv::Rect ClippedRect(const cv::Mat& image, int x0, int y0, int x1, int y1) {
  return cv::Rect(x0, y0, x1 - x0, y1 - y0) & cv::Rect(0, 0, image.cols, image.rows);
}

// The rectangle's walls and what they enclose, in pixels.
cv::Rect OuterPixels(const FloorPlan& plan, const RectM& rect) {
  const int t = plan.wall_thickness_px();
  return ClippedRect(plan.image(), plan.WallStart(plan.ToPixels(rect.x)),
                     plan.WallStart(plan.ToPixels(rect.y)),
                     plan.WallStart(plan.ToPixels(rect.x + rect.width)) + t,
                     plan.WallStart(plan.ToPixels(rect.y + rect.height)) + t);
}

}  // namespace

cv::Rect InnerCells(const FloorPlan& plan, const RectM& rect) {
  const int t = plan.wall_thickness_px();
  return ClippedRect(plan.image(), plan.WallStart(plan.ToPixels(rect.x)) + t,
                     plan.WallStart(plan.ToPixels(rect.y)) + t,
                     plan.WallStart(plan.ToPixels(rect.x + rect.width)),
                     plan.WallStart(plan.ToPixels(rect.y + rect.height)));
}

FloorPlan::FloorPlan(double width_m, double height_m, double resolution_m, double wall_thickness_m)
    : resolution_m_(resolution_m),
      wall_thickness_px_(
          std::max(1, static_cast<int>(std::lround(wall_thickness_m / resolution_m)))),
      image_(ToPixels(height_m), ToPixels(width_m), CV_8UC1, cv::Scalar(kUnknownGrey)) {}

int FloorPlan::ToPixels(double metres) const {
  return static_cast<int>(std::lround(metres / resolution_m_));
}

void DrawRoom(FloorPlan& plan, const RectM& room) { DrawRegion(plan, {room}); }

void DrawRegion(FloorPlan& plan, const std::vector<RectM>& parts) {
  cv::Mat& image = plan.image();
  cv::Mat outer = cv::Mat::zeros(image.size(), CV_8UC1);
  cv::Mat inner = cv::Mat::zeros(image.size(), CV_8UC1);
  for (const RectM& part : parts) {
    outer(OuterPixels(plan, part)).setTo(1);
    inner(InnerCells(plan, part)).setTo(1);
  }
  image.setTo(kWallGrey, outer);
  image.setTo(kFreeGrey, inner);
}

void DrawDoor(FloorPlan& plan, double x_m, double y_m, double width_m, WallDirection wall) {
  const int t = plan.wall_thickness_px();
  cv::Rect gap;
  if (wall == WallDirection::kHorizontal) {
    const int y0 = plan.WallStart(plan.ToPixels(y_m));
    gap = ClippedRect(plan.image(), plan.ToPixels(x_m - width_m / 2), y0,
                      plan.ToPixels(x_m + width_m / 2), y0 + t);
  } else {
    const int x0 = plan.WallStart(plan.ToPixels(x_m));
    gap = ClippedRect(plan.image(), x0, plan.ToPixels(y_m - width_m / 2), x0 + t,
                      plan.ToPixels(y_m + width_m / 2));
  }
  plan.image()(gap).setTo(kFreeGrey);
}

void DrawFurniture(FloorPlan& plan, const RectM& box) {
  plan.image()(ClippedRect(plan.image(), plan.ToPixels(box.x), plan.ToPixels(box.y),
                           plan.ToPixels(box.x + box.width), plan.ToPixels(box.y + box.height)))
      .setTo(kWallGrey);
}

void DrawNoiseDots(FloorPlan& plan, int count, uint32_t seed) {
  std::mt19937 random(seed);
  cv::Mat& image = plan.image();
  // Bounded retries: a plan with hardly any free space just gets fewer dots.
  for (int placed = 0, tries = 0; placed < count && tries < 100 * count; ++tries) {
    const int x = static_cast<int>(UniformIndex(random, image.cols));
    const int y = static_cast<int>(UniformIndex(random, image.rows));
    if (image.at<uint8_t>(y, x) != kFreeGrey) continue;
    image.at<uint8_t>(y, x) = kWallGrey;
    ++placed;
  }
}

void DrawMaze(FloorPlan& plan, const RectM& area, int cols, int rows, uint32_t seed) {
  const double cell_w = area.width / cols, cell_h = area.height / rows;
  auto cell_rect = [&](int col, int row) {
    return RectM{area.x + col * cell_w, area.y + row * cell_h, cell_w, cell_h};
  };
  for (int row = 0; row < rows; ++row) {
    for (int col = 0; col < cols; ++col) DrawRoom(plan, cell_rect(col, row));
  }

  // Depth-first search over the cells; each step opens the shared wall.
  std::mt19937 random(seed);
  std::vector<bool> visited(static_cast<size_t>(cols) * rows, false);
  std::vector<cv::Point> stack = {{0, 0}};
  visited[0] = true;
  const cv::Point steps[] = {{1, 0}, {-1, 0}, {0, 1}, {0, -1}};
  while (!stack.empty()) {
    const cv::Point cell = stack.back();
    std::vector<cv::Point> open;
    for (const cv::Point& step : steps) {
      const cv::Point next = cell + step;
      if (next.x >= 0 && next.y >= 0 && next.x < cols && next.y < rows &&
          !visited[next.y * cols + next.x]) {
        open.push_back(next);
      }
    }
    if (open.empty()) {
      stack.pop_back();
      continue;
    }
    const cv::Point next = open[UniformIndex(random, static_cast<uint32_t>(open.size()))];
    visited[next.y * cols + next.x] = true;
    stack.push_back(next);
    // The union of both cells' insides plus the wall between them.
    const cv::Rect a = InnerCells(plan, cell_rect(cell.x, cell.y));
    const cv::Rect b = InnerCells(plan, cell_rect(next.x, next.y));
    const int x0 = std::min(a.x, b.x), y0 = std::min(a.y, b.y);
    const int x1 = std::max(a.br().x, b.br().x), y1 = std::max(a.br().y, b.br().y);
    plan.image()(ClippedRect(plan.image(), x0, y0, x1, y1)).setTo(kFreeGrey);
  }
}

void WritePlanPng(const FloorPlan& plan, const std::string& path) {
  WritePngFile(path, plan.image());
}

std::string MapServerYaml(const FloorPlan& plan, const std::string& image_file, double origin_x_m,
                          double origin_y_m) {
  std::ostringstream yaml;
  yaml << "image: " << image_file << "\n"
       << "resolution: " << plan.resolution_m() << "\n"
       << "origin: [" << origin_x_m << ", " << origin_y_m << ", 0.0]\n"
       << "negate: 0\n"
       << "occupied_thresh: 0.65\n"
       << "free_thresh: 0.196\n";
  return yaml.str();
}

}  // namespace areagraph::floorplan

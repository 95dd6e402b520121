#pragma once

#include <cstdint>
#include <opencv2/core.hpp>
#include <string>
#include <vector>

namespace areagraph::floorplan {

// Grey values of drawn maps, as ROS map_server saves them: every one of them
// classifies the same under ag-import's default thresholds and under a
// map_server YAML with the usual thresholds (0.65 / 0.196).
inline constexpr uint8_t kFreeGrey = 254;
inline constexpr uint8_t kUnknownGrey = 205;
inline constexpr uint8_t kWallGrey = 0;

// A rectangle in metres: x to the right and y down from the plan's top-left
// corner, like image pixels, so that drawings read like the PNG they become.
struct RectM {
  double x = 0;
  double y = 0;
  double width = 0;
  double height = 0;
};

// Which way the wall that a door is cut into runs.
enum class WallDirection { kHorizontal, kVertical };

// A floor plan being drawn: an 8-bit grey image that starts all unknown.
// Walls are centred on the outlines of the rectangles passed to DrawRoom, so
// rooms that share an edge share one wall.
class FloorPlan {
 public:
  FloorPlan(double width_m, double height_m, double resolution_m = 0.05,
            double wall_thickness_m = 0.15);

  const cv::Mat& image() const { return image_; }
  cv::Mat& image() { return image_; }
  double resolution_m() const { return resolution_m_; }
  // Wall thickness after rounding to whole pixels (at least one).
  int wall_thickness_px() const { return wall_thickness_px_; }

  // The pixel boundary nearest to a coordinate in metres.
  int ToPixels(double metres) const;
  // First row/column of the wall band centred on pixel boundary `edge`.
  int WallStart(int edge) const { return edge - wall_thickness_px_ / 2; }

 private:
  double resolution_m_;
  int wall_thickness_px_;
  cv::Mat image_;
};

// The free cells inside a rectangle's walls (clipped to the image): what a
// room drawn with DrawRoom leaves free, and what its ground truth covers.
cv::Rect InnerCells(const FloorPlan& plan, const RectM& rect);

// A free room with walls around it. Draw rooms before the doors that open
// them: a room's walls cover whatever lies under them.
void DrawRoom(FloorPlan& plan, const RectM& room);

// One free area shaped like the union of `parts` (an L-shaped corridor, a
// room with an alcove), walled around its outline only.
void DrawRegion(FloorPlan& plan, const std::vector<RectM>& parts);

// Cuts a door `width_m` wide, centred at (x_m, y_m) on the centre line of a
// wall that runs in direction `wall`, making the whole wall thickness free.
void DrawDoor(FloorPlan& plan, double x_m, double y_m, double width_m, WallDirection wall);

// A solid obstacle such as a cupboard, desk or pillar.
void DrawFurniture(FloorPlan& plan, const RectM& box);

// `count` one-pixel obstacles on free cells, at places that depend only on
// `seed`: the sensor noise that outlier removal has to deal with.
void DrawNoiseDots(FloorPlan& plan, int count, uint32_t seed);

// A perfect maze of cols x rows square cells filling `area`, carved by a
// depth-first search that depends only on `seed`. Neighbouring cells are
// joined along their whole side, leaving short wall posts at the corners.
void DrawMaze(FloorPlan& plan, const RectM& area, int cols, int rows, uint32_t seed);

// Writes the plan as an 8-bit grey PNG through WritePngFile (so "-" is
// standard output). Throws InputError on failure.
void WritePlanPng(const FloorPlan& plan, const std::string& path);

// ROS map_server YAML text for the image file `image_file` (relative to the
// YAML) of `plan`, with the map origin at (origin_x_m, origin_y_m).
std::string MapServerYaml(const FloorPlan& plan, const std::string& image_file, double origin_x_m,
                          double origin_y_m);

}  // namespace areagraph::floorplan

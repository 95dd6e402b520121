// ag-make-example-maps: draws the small maps in examples/ so that they can be
// re-made (and changed) instead of being opaque binary files.
#include <CLI/CLI.hpp>
#include <fstream>
#include <iostream>
#include <string>

#include "stages/common/command_line.h"
#include "tools/example_maps/floor_plan.h"

namespace areagraph::floorplan {
namespace {

constexpr double kDoorWidthM = 0.9;

// Two 5 m x 5 m rooms side by side, joined by one door.
FloorPlan TwoRooms() {
  FloorPlan plan(12, 7);
  DrawRoom(plan, {1, 1, 5, 5});
  DrawRoom(plan, {6, 1, 5, 5});
  DrawDoor(plan, 6, 3.5, kDoorWidthM, WallDirection::kVertical);
  DrawFurniture(plan, {2, 1.5, 1.6, 0.8});
  DrawFurniture(plan, {9.6, 4.2, 0.8, 1.2});
  DrawNoiseDots(plan, 12, /*seed=*/2);
  return plan;
}

// A 2 m wide corridor with three rooms on each side.
FloorPlan CorridorRooms() {
  FloorPlan plan(20, 12);
  DrawRoom(plan, {1, 5, 18, 2});
  for (int i = 0; i < 3; ++i) {
    DrawRoom(plan, {1.0 + 6 * i, 1, 6, 4});
    DrawRoom(plan, {1.0 + 6 * i, 7, 6, 4});
  }
  for (const double x : {4.0, 10.0, 16.5}) {
    DrawDoor(plan, x, 5, kDoorWidthM, WallDirection::kHorizontal);
  }
  for (const double x : {2.5, 10.5, 17.0}) {
    DrawDoor(plan, x, 7, 1.0, WallDirection::kHorizontal);
  }
  DrawFurniture(plan, {2, 1.6, 2.0, 0.8});
  DrawFurniture(plan, {8.5, 2.0, 1.2, 1.2});
  DrawFurniture(plan, {14, 8.5, 0.6, 2.0});
  DrawFurniture(plan, {9, 9.5, 1.6, 0.7});
  DrawNoiseDots(plan, 30, /*seed=*/3);
  return plan;
}

// An L-shaped corridor serving five rooms of different sizes, one of them
// reached through its neighbour, with desks, cupboards and noise.
FloorPlan OfficeSmall() {
  FloorPlan plan(18, 15);
  DrawRegion(plan, {{1, 6, 16, 2}, {1, 6, 2, 8}});
  DrawRoom(plan, {1, 1, 5, 5});
  DrawRoom(plan, {6, 1, 4, 5});
  DrawRoom(plan, {10, 1, 7, 5});
  DrawRoom(plan, {3, 8, 6, 6});
  DrawRoom(plan, {9, 8, 8, 6});
  DrawDoor(plan, 3.5, 6, kDoorWidthM, WallDirection::kHorizontal);
  DrawDoor(plan, 8.0, 6, kDoorWidthM, WallDirection::kHorizontal);
  DrawDoor(plan, 10, 3.5, 0.8, WallDirection::kVertical);
  DrawDoor(plan, 3, 11, kDoorWidthM, WallDirection::kVertical);
  DrawDoor(plan, 13, 8, 1.0, WallDirection::kHorizontal);
  DrawFurniture(plan, {1.5, 1.5, 1.6, 0.8});
  DrawFurniture(plan, {4.6, 2.5, 0.8, 1.6});
  DrawFurniture(plan, {11, 1.5, 3.0, 0.6});
  DrawFurniture(plan, {15.5, 3.5, 0.6, 0.6});
  DrawFurniture(plan, {5, 12.5, 2.0, 0.8});
  DrawFurniture(plan, {10, 10, 1.6, 0.8});
  DrawFurniture(plan, {14, 10, 1.6, 0.8});
  DrawFurniture(plan, {16.2, 12.5, 0.4, 0.4});
  DrawNoiseDots(plan, 40, /*seed=*/1);
  return plan;
}

void WriteText(const std::string& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  if (!(out << text)) throw std::runtime_error("cannot write '" + path + "'");
}

}  // namespace
}  // namespace areagraph::floorplan

int main(int argc, char** argv) {
  using namespace areagraph::floorplan;
  CLI::App app{
      "Draws the example maps (0.05 m/px; free 254, walls 0, unknown 205) into a folder: "
      "two_rooms.png, corridor_rooms.png, office_small.png and office_small.yaml. The "
      "drawings are deterministic, so re-running reproduces the files in examples/."};
  std::string out_dir = ".";
  app.add_option("--out", out_dir, "folder to write to (e.g. examples)")->capture_default_str();
  return areagraph::RunCommand("ag-make-example-maps", app, argc, argv, [&] {
    WritePlanPng(TwoRooms(), out_dir + "/two_rooms.png");
    WritePlanPng(CorridorRooms(), out_dir + "/corridor_rooms.png");
    const FloorPlan office = OfficeSmall();
    WritePlanPng(office, out_dir + "/office_small.png");
    WriteText(out_dir + "/office_small.yaml",
              MapServerYaml(office, "office_small.png", -2.0, -1.5));
    std::cout << "wrote two_rooms.png, corridor_rooms.png, office_small.png, office_small.yaml to "
              << out_dir << "\n";
    return 0;
  });
}

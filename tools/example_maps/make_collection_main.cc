// ag-make-collection: writes a synthetic map collection for benchmarks and
// runner tests: random office floors (see random_floor_plan.h).
#include <CLI/CLI.hpp>
#include <cstdio>
#include <filesystem>
#include <iostream>

#include "stages/common/command_line.h"
#include "tools/example_maps/random_floor_plan.h"

int main(int argc, char** argv) {
  using namespace areagraph::floorplan;
  CLI::App app{
      "Writes COUNT random office floors (0.05 m/px PNGs, 2-4 rooms on each side of a "
      "corridor, doors, furniture, noise) into OUT, 100 per subfolder (OUT/000/map_00000.png, "
      "...). The same seed gives the same files."};
  int count = 100;
  unsigned seed = 1;
  std::string out_dir;
  app.add_option("--count", count, "number of maps")
      ->capture_default_str()
      ->check(CLI::Range(1, 1000000));
  app.add_option("--seed", seed, "seed of the first map; map i uses seed + i")
      ->capture_default_str();
  app.add_option("OUT", out_dir, "folder to write to")->required();
  return areagraph::RunCommand("ag-make-collection", app, argc, argv, [&] {
    for (int i = 0; i < count; ++i) {
      char folder[16], name[32];
      std::snprintf(folder, sizeof(folder), "%03d", i / 100);
      std::snprintf(name, sizeof(name), "map_%05d.png", i);
      const std::filesystem::path dir = std::filesystem::path(out_dir) / folder;
      std::filesystem::create_directories(dir);
      WritePlanPng(RandomOfficePlan(seed + static_cast<unsigned>(i)), (dir / name).string());
    }
    std::cout << "wrote " << count << " maps to " << out_dir << "\n";
    return 0;
  });
}

// ag-make-benchmark: writes one part of the generated quality benchmark:
// floors with their ground truth (see benchmark_floor.h).
#include <CLI/CLI.hpp>
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <opencv2/imgcodecs.hpp>

#include "stages/common/command_line.h"
#include "tools/example_maps/benchmark_floor.h"

namespace areagraph::floorplan {
namespace {

void WriteFloor(uint32_t seed, const std::filesystem::path& out, std::ofstream& index) {
  const BenchmarkFloor floor = RandomBenchmarkFloor(seed);
  const std::string name = BenchmarkFloorName(seed);
  WritePlanPng(floor.plan, (out / "maps" / (name + ".png")).string());
  std::ofstream yaml(out / "maps" / (name + ".yaml"));
  yaml << MapServerYaml(floor.plan, name + ".png", 0, 0);
  if (!yaml) throw std::runtime_error("cannot write the YAML of " + name);
  const std::string truth = (out / "gt" / (name + ".png")).string();
  if (!cv::imwrite(truth, floor.truth)) throw std::runtime_error("cannot write '" + truth + "'");
  double narrowest = 0, widest = 0;
  for (const DoorM& door : floor.layout.doors) {
    narrowest = narrowest == 0 ? door.width : std::min(narrowest, door.width);
    widest = std::max(widest, door.width);
  }
  index << name << '\t' << seed << '\t' << floor.layout.name << '\t' << floor.plan.resolution_m()
        << '\t' << floor.layout.corridor_width_m << '\t' << narrowest << '\t' << widest << '\t'
        << floor.layout.zones.size() << '\n';
}

}  // namespace
}  // namespace areagraph::floorplan

int main(int argc, char** argv) {
  using namespace areagraph::floorplan;
  CLI::App app{
      "Writes one part of the generated quality benchmark into OUT: OUT/maps/floor_<seed>.png "
      "with its map_server YAML (0.025-0.1 m/px), OUT/gt/floor_<seed>.png (16-bit ground "
      "truth: one label per room, hall and corridor system; 0 = none) and OUT/index.tsv "
      "(layout, resolution, corridor and door widths per floor). The tuning part is seeds 1-30, "
      "the held-out part seeds 100001-100030, the extra tuning part (tuning-extra) seeds "
      "1001-1100; the same seed always gives the same floor."};
  std::string part_name = kTuningPart.name;
  int count = -1;
  std::string out_dir;
  app.add_option("--part", part_name, "tuning, tuning-extra or held-out")
      ->capture_default_str()
      ->check(CLI::IsMember({kTuningPart.name, kTuningExtraPart.name, kHeldOutPart.name}));
  app.add_option("--count", count, "only the first COUNT floors of the part")
      ->check(CLI::Range(1, 100000));
  app.add_option("OUT", out_dir, "folder to write to")->required();
  return areagraph::RunCommand("ag-make-benchmark", app, argc, argv, [&] {
    const BenchmarkPart part = part_name == kTuningPart.name        ? kTuningPart
                               : part_name == kTuningExtraPart.name ? kTuningExtraPart
                                                                    : kHeldOutPart;
    if (count < 0 || count > part.count) count = part.count;
    const std::filesystem::path out(out_dir);
    std::filesystem::create_directories(out / "maps");
    std::filesystem::create_directories(out / "gt");
    std::ofstream index(out / "index.tsv");
    index
        << "name\tseed\tlayout\tresolution_m\tcorridor_m\tnarrowest_door_m\twidest_door_m\tzones\n";
    for (int i = 0; i < count; ++i) WriteFloor(part.first_seed + i, out, index);
    if (!index) throw std::runtime_error("cannot write " + (out / "index.tsv").string());
    std::cout << "wrote " << count << " floors of the " << part.name << " part to " << out_dir
              << "\n";
    return 0;
  });
}

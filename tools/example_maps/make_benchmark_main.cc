// ag-make-benchmark: writes one part of the generated quality benchmark:
// floors with their ground truth (see benchmark_floor.h).
#include <CLI/CLI.hpp>
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <opencv2/imgcodecs.hpp>
#include <string>
#include <vector>

#include "stages/common/command_line.h"
#include "tools/example_maps/benchmark_floor.h"

namespace areagraph::floorplan {
namespace {

constexpr BenchmarkPart kParts[] = {kTuningPart, kTuningExtraPart, kHeldOutPart, kPublicTuningPart,
                                    kPublicHeldOutPart};

void WriteFloor(const BenchmarkPart& part, uint32_t seed, const std::filesystem::path& out,
                std::ofstream& index) {
  const BenchmarkFloor floor = MakeBenchmarkFloor(part, seed);
  const std::string name = BenchmarkFloorName(part, seed);
  WritePlanPng(floor.plan, (out / "maps" / (name + ".png")).string());
  std::ofstream yaml(out / "maps" / (name + ".yaml"));
  yaml << MapServerYaml(floor.plan, name + ".png", 0, 0);
  if (!yaml) throw std::runtime_error("cannot write the YAML of " + name);
  const std::string truth = (out / "gt" / (name + ".png")).string();
  if (!cv::imwrite(truth, floor.truth)) throw std::runtime_error("cannot write '" + truth + "'");
  std::ofstream kinds(out / "gt" / (name + ".kinds.tsv"));
  kinds << GroundTruthKindsTsv(floor.layout);
  if (!kinds) throw std::runtime_error("cannot write the kinds of " + name);
  // Doors only: a room open along a whole side has no door.
  double narrowest = 0, widest = 0;
  for (const DoorM& door : floor.layout.doors) {
    if (door.whole_side) continue;
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
      "Writes one part of the generated quality benchmark into OUT: OUT/maps/<name>.png "
      "with its map_server YAML, OUT/gt/<name>.png (16-bit ground truth: one label per room, "
      "hall and corridor system; 0 = none), OUT/gt/<name>.kinds.tsv (each label's kind: room, "
      "corridor or dead_end) and OUT/index.tsv (layout, resolution, narrowest corridor and door "
      "widths per floor). Office floors (floor_<seed>, 0.025-0.1 m/px): the tuning part is "
      "seeds 1-30, the held-out part seeds 100001-100030, the extra tuning part (tuning-extra) "
      "seeds 1001-1100. Large public buildings (public_<seed>, 100-200 m across, 0.05-0.1 "
      "m/px): public-tuning is seeds 2001-2020, public-held-out seeds 200001-200020. The same "
      "seed always gives the same floor."};
  std::string part_name = kTuningPart.name;
  int count = -1;
  std::string out_dir;
  std::vector<std::string> part_names;
  for (const BenchmarkPart& part : kParts) part_names.push_back(part.name);
  app.add_option("--part", part_name,
                 "tuning, tuning-extra, held-out, public-tuning or public-held-out")
      ->capture_default_str()
      ->check(CLI::IsMember(part_names));
  app.add_option("--count", count, "only the first COUNT floors of the part")
      ->check(CLI::Range(1, 100000));
  app.add_option("OUT", out_dir, "folder to write to")->required();
  return areagraph::RunCommand("ag-make-benchmark", app, argc, argv, [&] {
    const BenchmarkPart part = *std::find_if(std::begin(kParts), std::end(kParts),
                                             [&](auto& p) { return part_name == p.name; });
    if (count < 0 || count > part.count) count = part.count;
    const std::filesystem::path out(out_dir);
    std::filesystem::create_directories(out / "maps");
    std::filesystem::create_directories(out / "gt");
    std::ofstream index(out / "index.tsv");
    index
        << "name\tseed\tlayout\tresolution_m\tcorridor_m\tnarrowest_door_m\twidest_door_m\tzones\n";
    for (int i = 0; i < count; ++i) WriteFloor(part, part.first_seed + i, out, index);
    if (!index) throw std::runtime_error("cannot write " + (out / "index.tsv").string());
    std::cout << "wrote " << count << " floors of the " << part.name << " part to " << out_dir
              << "\n";
    return 0;
  });
}

// ag-test-send-map: publishes a map image as a grid_map_t on LCM channel MAP,
// or raw garbage bytes there, for the tests of ag-live.
#include <CLI/CLI.hpp>
#include <chrono>
#include <iostream>
#include <string>

#include "common/error.h"
#include "runner/live/area_graph_publisher.h"
#include "runner/live/lcm_connection.h"
#include "runner/live/lcm_conversion.h"
#include "stages/common/command_line.h"
#include "stages/import/import_stage.h"

namespace areagraph {
namespace {

int SendMap(const std::string& url, const std::string& image, std::string name, int garbage_bytes) {
  const std::unique_ptr<lcm::LCM> lcm = OpenLcm(url);
  if (garbage_bytes > 0) {
    std::string garbage(static_cast<size_t>(garbage_bytes), '\0');
    for (size_t i = 0; i < garbage.size(); ++i) garbage[i] = static_cast<char>(i * 37 + 11);
    if (lcm->publish(kGridMapChannel, garbage.data(), static_cast<unsigned>(garbage.size())) != 0) {
      throw Error("cannot publish on " + std::string(kGridMapChannel));
    }
    std::cout << "sent " << garbage_bytes << " garbage bytes on " << kGridMapChannel << "\n";
  }
  if (image.empty()) return 0;
  const proto::GridMap grid = ImportGridMap(ReadImportSource(image), proto::ImportOptions());
  if (name.empty()) name = DefaultMapName(image);
  const int64_t utime = std::chrono::duration_cast<std::chrono::microseconds>(
                            std::chrono::system_clock::now().time_since_epoch())
                            .count();
  const areagraph_lcm::grid_map_t message = ToLcmGridMap(name, utime, grid);
  if (lcm->publish(kGridMapChannel, &message) != 0) {
    throw Error("cannot publish on " + std::string(kGridMapChannel));
  }
  std::cout << "sent " << name << " (" << message.width << "x" << message.height << " cells) on "
            << kGridMapChannel << "\n";
  return 0;
}

}  // namespace
}  // namespace areagraph

int main(int argc, char** argv) {
  using namespace areagraph;
  CLI::App app{
      "Test helper: publishes IMAGE (imported with default options) as a grid_map_t on "
      "LCM channel MAP; --garbage sends that many junk bytes there first."};
  std::string url = kDefaultLcmUrl, image, name;
  int garbage_bytes = 0;
  app.add_option("--url", url, "LCM URL")->capture_default_str();
  app.add_option("--name", name, "map name (default: the image's stem)");
  app.add_option("--garbage", garbage_bytes, "junk bytes to send on MAP first")
      ->check(CLI::Range(0, 1 << 20));
  app.add_option("IMAGE", image, "map image (PNG, PGM) with optional YAML beside it");
  return RunCommand("ag-test-send-map", app, argc, argv,
                    [&] { return SendMap(url, image, name, garbage_bytes); });
}

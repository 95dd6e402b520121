// ag-bench-tile: repeats one map N x N times into one connected map, the
// speed benchmark's scale series (a campus made of copies of one building).
#include <CLI/CLI.hpp>
#include <iostream>
#include <opencv2/imgcodecs.hpp>
#include <string>

#include "common/error.h"
#include "stages/common/command_line.h"
#include "tools/bench/map_tiling.h"

int main(int argc, char** argv) {
  CLI::App app{
      "Writes MAP repeated N x N times as one grey PNG, each copy joined to its right and lower "
      "neighbour by a 1 m corridor (walled, at the row and column of the map's longest straight "
      "run of free cells), so that the free space stays one piece. Free is grey >= 250, as "
      "ag-import reads maps without a YAML. For tools/bench-speed.sh's scale series."};
  std::string in_path, out_path;
  int tiles = 2;
  app.add_option("MAP", in_path, "map image")->required();
  app.add_option("OUT", out_path, "PNG to write")->required();
  app.add_option("--tiles", tiles, "copies per side")
      ->capture_default_str()
      ->check(CLI::Range(1, 64));
  return areagraph::RunCommand("ag-bench-tile", app, argc, argv, [&] {
    const cv::Mat map = cv::imread(in_path, cv::IMREAD_GRAYSCALE);
    if (map.empty()) throw areagraph::InputError("cannot read the image '" + in_path + "'");
    const cv::Mat tiled = areagraph::TileMap(map, tiles);
    if (!cv::imwrite(out_path, tiled)) {
      throw areagraph::InputError("cannot write '" + out_path + "'");
    }
    std::cout << "wrote " << out_path << " (" << tiled.cols << " x " << tiled.rows << " px)\n";
    return 0;
  });
}

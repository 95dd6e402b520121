// ag-render: draws a stage's artifact over its map as a PNG.
#include <google/protobuf/arena.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <opencv2/imgproc.hpp>
#include <utility>

#include "common/error.h"
#include "common/process_setup/page_fault_thrift.h"
#include "common/text.h"
#include "proto/pipeline_options.pb.h"
#include "stages/common/command_line.h"
#include "stages/common/output_file.h"
#include "stages/common/png_file.h"
#include "stages/pipeline/stage.h"
#include "tools/render/artifact_drawing.h"
#include "tools/render/map_png.h"

namespace areagraph {
namespace {

// The cells to draw under a stage's artifact: the raw map for import and
// clean (so removed obstacles show), the cleaned map after that.
struct BaseMap {
  proto::MapFrame frame;
  std::string cells;
};

BaseMap ReadBaseMap(ArtifactStore& store, const std::string& map, const StageInfo& stage) {
  BaseMap base;
  if (SameStage(stage, kImportStage) || SameStage(stage, kCleanStage)) {
    auto grid = ReadHeadArtifact<proto::GridMap>(store, map, kImportStage);
    base.frame = grid.frame();
    base.cells = std::move(*grid.mutable_cells());
  } else {
    auto cleaned = ReadHeadArtifact<proto::CleanedMap>(store, map, kCleanStage);
    base.frame = cleaned.frame();
    base.cells = std::move(*cleaned.mutable_cells());
  }
  return base;
}

// The canvas above which the heap grows by huge pages once more: at lab_a
// tiled 2 x 2 (1.5 Mpx) it saved nothing, at 8 x 8 (24 Mpx) 31 000 of 31 600
// faults (docs/performance.md, "Memory between stages").
constexpr double kHugePageCanvasPixels = 4e6;

// The canvas pixels of a window "X,Y,W,H" given in map cells.
cv::Rect CropWindow(const std::string& text, int scale, const cv::Size& size) {
  int x = 0, y = 0, w = 0, h = 0;
  char tail = 0;
  if (std::sscanf(text.c_str(), "%d,%d,%d,%d%c", &x, &y, &w, &h, &tail) != 4 || x < 0 || y < 0 ||
      w <= 0 || h <= 0) {
    throw InputError("--crop must be X,Y,W,H in map cells (W and H positive), got '" + text + "'");
  }
  const int s = scale;
  const cv::Rect window =
      cv::Rect(x * s, y * s, w * s, h * s) & cv::Rect(0, 0, size.width, size.height);
  if (window.area() == 0) throw InputError("--crop '" + text + "' lies outside the map");
  return window;
}

// The most pixels a picture may have: what ag-import takes for a map
// (import.max_pixels' default). The whole map is drawn at --scale before
// --crop or --width cut it, so an unbounded scale would ask for gigabytes.
const double kMaxPicturePixels = static_cast<double>(proto::ImportOptions().max_pixels());

void CheckPictureSize(int width_px, int height_px, int scale) {
  const double pixels = static_cast<double>(width_px) * height_px * scale * scale;
  if (scale == 1 || pixels <= kMaxPicturePixels) return;  // scale 1: the map's own size
  const int most = std::max(
      1,
      static_cast<int>(std::sqrt(kMaxPicturePixels / std::max(1.0, double{width_px} * height_px))));
  throw InputError("--scale " + std::to_string(scale) + " would draw the " +
                   std::to_string(width_px) + " x " + std::to_string(height_px) + " map as " +
                   FormatNumber(pixels) + " pixels, more than " + FormatNumber(kMaxPicturePixels) +
                   "; use --scale " + std::to_string(most) + " or less");
}

void Render(ArtifactStore& store, const std::string& map, const std::string& stage, int scale,
            bool doors, int width, const std::string& crop, const std::string& out) {
  const StageDefinition& definition = FindStage(stage, "--stage");
  const BaseMap base = ReadBaseMap(store, map, definition.info);
  const int width_px = base.frame.width_px(), height_px = base.frame.height_px();
  if (scale <= 0) scale = DefaultScale(width_px, height_px);
  CheckPictureSize(width_px, height_px, scale);
  // The import's picture is the bare map: written from its cells
  // (EncodeMapPng), without a canvas.
  if (SameStage(definition.info, kImportStage) && !doors && crop.empty() &&
      (width <= 0 || width_px * scale <= width)) {
    WriteOutputFile(out, EncodeMapPng(base.cells, width_px, height_px, scale));
    return;
  }
  // A big canvas, its masks and the parsed artifact outgrow the heap's
  // reserve, and glibc maps each buffer over 32 MB (the BGR picture of lab_a
  // tiled 8 x 8 is 71 MB) in 4-kB pages: its Voronoi picture faulted 31 000
  // pages, 0.85 of its 2 s of CPU (docs/performance.md, "Memory between stages").
  const double canvas_pixels = static_cast<double>(width_px) * height_px * scale * scale;
  if (canvas_pixels > kHugePageCanvasPixels) {
    GrowFaultThriftyHeap(static_cast<size_t>(std::min(canvas_pixels * 40, double{1 << 30})));
  }
  Canvas canvas(base.cells, width_px, height_px, scale);
  // The others are parsed into an arena, which frees tens of thousands of
  // messages (a Voronoi diagram's edges) at once.
  if (!SameStage(definition.info, kImportStage)) {
    google::protobuf::Arena arena;
    google::protobuf::Message* artifact = definition.prototype->New(&arena);
    ParseHeadArtifact(store, map, definition.info, artifact, nullptr);
    DrawArtifact(*artifact, canvas);
  }
  if (doors) {
    const auto cut = ReadHeadArtifact<proto::CutGraph>(store, map, kCutStage);
    DrawDetectedWidths(cut.room_width(), cut.frame().resolution_m(), canvas);
  }
  // A bare map (a cleaned map with nothing removed) is written from its
  // greys: the same file, without a BGR picture to make and scan for its
  // colours.
  const cv::Mat grey = canvas.UntouchedGrey();
  if (!grey.empty() && crop.empty() && (width <= 0 || grey.cols <= width)) {
    WriteGreyPngFileAsColour(out, grey);
    return;
  }
  cv::Mat picture = canvas.image();
  if (!crop.empty()) picture = picture(CropWindow(crop, canvas.scale(), picture.size())).clone();
  if (width > 0 && picture.cols > width) {
    const double factor = static_cast<double>(width) / picture.cols;
    cv::resize(picture.clone(), picture, cv::Size(), factor, factor, cv::INTER_AREA);
  }
  WritePngFile(out, picture);
}

}  // namespace
}  // namespace areagraph

int main(int argc, char** argv) {
  // A render writes each of its big buffers (the payloads, their parsed
  // arrays, the canvas and its masks) once: faulting them in was half of its
  // CPU time (docs/performance.md, "Memory between stages").
  areagraph::UseFaultThriftyHeap(size_t{256} << 20);
  // OpenCV's functions run on the calling thread: a picture is drawn in
  // milliseconds, and its parallel loops would load TBB (common/
  // lazy_libraries.cc) and start its workers, 5 ms of CPU in a 35-ms
  // picture. 0 (not 1, which starts a TBB arena) skips TBB entirely, which
  // also keeps ag-render's own libstdc++ the only one in the process
  // (tools/render/CMakeLists.txt).
  cv::setNumThreads(0);
  CLI::App app{"Draws the head artifact of one stage over its map as a PNG."};
  std::string store_path = "areagraph.db", map, stage = areagraph::kMergeStage.name, out;
  int scale = 0;
  bool doors = false;
  int width = 0;
  app.add_option("--store", store_path, "SQLite artifact store")->capture_default_str();
  app.add_option("--map", map, "map name")->required();
  app.add_option("--stage", stage, areagraph::StageNameList())->capture_default_str();
  app.add_option("--out", out, "PNG file to write, or - for standard output")->required();
  app.add_flag("--doors", doors,
               "also draw the doors (rings) and corridors (dots) that ag-cut found for "
               "cut.room_width_m=auto");
  app.add_option("--width", width, "shrink the picture to at most this many pixels wide");
  app.add_option("--scale", scale,
                 "output pixels per map cell, 1 to 16 (default: the most that keeps the picture "
                 "within 1000 px, at least 1)")
      ->check(CLI::Range(1, 16));
  std::string crop;
  app.add_option("--crop", crop, "draw only the window X,Y,W,H (map cells; with --scale to zoom)");
  return areagraph::RunCommand("ag-render", app, argc, argv, [&] {
    auto store = areagraph::OpenArtifactStore(store_path, areagraph::StoreMode::kReadOnly);
    if (width < 0) throw areagraph::InputError("--width must be positive");
    areagraph::Render(*store, map, stage, scale, doors, width, crop, out);
    if (!areagraph::IsStandardOutput(out)) std::cout << "wrote " << out << "\n";
    return 0;
  });
}

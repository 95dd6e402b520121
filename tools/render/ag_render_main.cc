// ag-render: draws a stage's artifact over its map as a PNG.
#include <CLI/CLI.hpp>
#include <iostream>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "common/error.h"
#include "stages/common/command_line.h"
#include "stages/common/stage.h"
#include "tools/render/artifact_drawing.h"

namespace areagraph {
namespace {

// The cells to draw under a stage's artifact: the raw map for import and
// clean (so removed obstacles show), the cleaned map after that.
Canvas BaseCanvas(ArtifactStore& store, const std::string& map, const StageInfo& stage, int scale) {
  proto::MapFrame frame;
  std::string cells;
  if (SameStage(stage, kImportStage) || SameStage(stage, kCleanStage)) {
    const auto grid = ReadHeadArtifact<proto::GridMap>(store, map, kImportStage);
    frame = grid.frame();
    cells = grid.cells();
  } else {
    const auto cleaned = ReadHeadArtifact<proto::CleanedMap>(store, map, kCleanStage);
    frame = cleaned.frame();
    cells = cleaned.cells();
  }
  if (scale <= 0) scale = DefaultScale(frame.width_px(), frame.height_px());
  return Canvas(cells, frame.width_px(), frame.height_px(), scale);
}

void Render(ArtifactStore& store, const std::string& map, const std::string& stage, int scale,
            bool doors, int width, const std::string& out) {
  const StageDefinition& definition = FindStage(stage, "--stage");
  Canvas canvas = BaseCanvas(store, map, definition.info, scale);
  const MessagePtr artifact(definition.prototype->New());
  ParseHeadArtifact(store, map, definition.info, artifact.get(), nullptr);
  DrawArtifact(*artifact, canvas);
  if (doors) {
    const auto cut = ReadHeadArtifact<proto::CutGraph>(store, map, kCutStage);
    DrawDetectedWidths(cut.room_width(), cut.frame().resolution_m(), canvas);
  }
  cv::Mat picture = canvas.image();
  if (width > 0 && picture.cols > width) {
    const double factor = static_cast<double>(width) / picture.cols;
    cv::resize(canvas.image(), picture, cv::Size(), factor, factor, cv::INTER_AREA);
  }
  bool written = false;
  try {
    written = cv::imwrite(out, picture, {cv::IMWRITE_PNG_COMPRESSION, 9});
  } catch (const cv::Exception&) {
  }
  if (!written) throw InputError("cannot write PNG '" + out + "'");
}

}  // namespace
}  // namespace areagraph

int main(int argc, char** argv) {
  CLI::App app{"Draws the head artifact of one stage over its map as a PNG."};
  std::string store_path = "areagraph.db", map, stage = areagraph::kMergeStage.name, out;
  int scale = 0;
  bool doors = false;
  int width = 0;
  app.add_option("--store", store_path, "SQLite artifact store")->capture_default_str();
  app.add_option("--map", map, "map name")->required();
  app.add_option("--stage", stage, areagraph::StageNameList())->capture_default_str();
  app.add_option("--out", out, "PNG file to write")->required();
  app.add_flag("--doors", doors,
               "also draw the doors (rings) and corridors (dots) that ag-cut found for "
               "cut.room_width_m=auto");
  app.add_option("--width", width, "shrink the picture to at most this many pixels wide");
  app.add_option("--scale", scale, "output pixels per map cell (default: about 1600 px wide)");
  return areagraph::RunCommand("ag-render", app, argc, argv, [&] {
    if (scale < 0 || scale > 16) throw areagraph::InputError("--scale must be between 1 and 16");
    auto store = areagraph::OpenArtifactStore(store_path, areagraph::StoreMode::kReadOnly);
    if (width < 0) throw areagraph::InputError("--width must be positive");
    areagraph::Render(*store, map, stage, scale, doors, width, out);
    std::cout << "wrote " << out << "\n";
    return 0;
  });
}

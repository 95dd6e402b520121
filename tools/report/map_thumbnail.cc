#include "tools/report/map_thumbnail.h"

#include <algorithm>
#include <opencv2/imgcodecs.hpp>  // the IMWRITE_ flags
#include <opencv2/imgproc.hpp>

#include "proto/artifacts.pb.h"
#include "stages/common/image_codecs.h"
#include "stages/pipeline/stage.h"
#include "tools/render/artifact_drawing.h"

namespace areagraph {
namespace {

const ArtifactRecord* StageArtifact(const std::vector<ArtifactRecord>& run,
                                    const StageInfo& stage) {
  for (const ArtifactRecord& artifact : run) {
    if (artifact.stage == stage.name) return &artifact;
  }
  return nullptr;
}

// The cells and frame of the cleaned map, else of the grid map.
bool BaseCells(const std::vector<ArtifactRecord>& run, std::string* cells, proto::MapFrame* frame) {
  proto::CleanedMap cleaned;
  proto::GridMap grid;
  if (const ArtifactRecord* clean = StageArtifact(run, kCleanStage);
      clean != nullptr && cleaned.ParseFromString(clean->payload)) {
    *cells = cleaned.cells();
    *frame = cleaned.frame();
  } else if (const ArtifactRecord* import = StageArtifact(run, kImportStage);
             import != nullptr && grid.ParseFromString(import->payload)) {
    *cells = grid.cells();
    *frame = grid.frame();
  } else {
    return false;
  }
  return frame->width_px() > 0 && frame->height_px() > 0 &&
         static_cast<int64_t>(cells->size()) ==
             static_cast<int64_t>(frame->width_px()) * frame->height_px();
}

}  // namespace

std::string MapThumbnailPng(const std::vector<ArtifactRecord>& run, int max_side) {
  std::string cells;
  proto::MapFrame frame;
  if (!BaseCells(run, &cells, &frame)) return "";
  Canvas canvas(cells, frame.width_px(), frame.height_px(), 1);
  proto::AreaGraph graph;
  // The published graph (match: stable ids as labels), else merge's.
  const ArtifactRecord* published = StageArtifact(run, kMatchStage);
  if (published == nullptr) published = StageArtifact(run, kMergeStage);
  if (published != nullptr && graph.ParseFromString(published->payload)) {
    DrawAreaGraph(graph, canvas);
  }
  const cv::Mat& full = canvas.image();
  const double factor =
      std::min(1.0, static_cast<double>(max_side) / std::max(full.cols, full.rows));
  cv::Mat small;
  cv::resize(full, small, cv::Size(), factor, factor, cv::INTER_AREA);
  std::vector<uchar> bytes;
  if (!EncodeImage(".png", small, &bytes, {cv::IMWRITE_PNG_COMPRESSION, 9})) return "";
  return std::string(bytes.begin(), bytes.end());
}

}  // namespace areagraph

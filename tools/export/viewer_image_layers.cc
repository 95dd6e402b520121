// The viewer's raster layers: the grid map and what cleaning changed.
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>  // the IMWRITE_ flags
#include <vector>

#include "common/error.h"
#include "stages/common/image_codecs.h"
#include "tools/export/svg_path.h"
#include "tools/export/viewer_layers.h"

namespace areagraph {
namespace {

// The same greys as ag-render's pictures.
constexpr uint8_t kFreeGrey = 255, kOccupiedGrey = 40, kUnknownGrey = 200;

// PNG bytes of a one-channel image.
std::string EncodePng(const cv::Mat& image) {
  std::vector<uchar> bytes;
  // Run-length deflate: as small as level 9 on maps (few grey values in long
  // runs) at half its time.
  if (!EncodeImage(".png", image, &bytes,
                   {cv::IMWRITE_PNG_COMPRESSION, 9, cv::IMWRITE_PNG_STRATEGY,
                    cv::IMWRITE_PNG_STRATEGY_RLE})) {
    throw Error("cannot encode a viewer layer as PNG");
  }
  return std::string(bytes.begin(), bytes.end());
}

// Throws StoreError when the cells do not fill the frame (a damaged artifact).
void CheckCells(const std::string& cells, const proto::MapFrame& frame) {
  const int64_t expected = static_cast<int64_t>(frame.width_px()) * frame.height_px();
  if (frame.width_px() <= 0 || frame.height_px() <= 0 ||
      static_cast<int64_t>(cells.size()) != expected) {
    throw StoreError("a map artifact's cells do not match its frame");
  }
}

}  // namespace

std::string GridMapPng(const proto::GridMap& grid) {
  CheckCells(grid.cells(), grid.frame());
  cv::Mat image(grid.frame().height_px(), grid.frame().width_px(), CV_8UC1);
  for (size_t i = 0; i < grid.cells().size(); ++i) {
    const uint8_t cell = static_cast<uint8_t>(grid.cells()[i]);
    image.data[i] = cell == proto::CELL_FREE       ? kFreeGrey
                    : cell == proto::CELL_OCCUPIED ? kOccupiedGrey
                                                   : kUnknownGrey;
  }
  return EncodePng(image);
}

viewer::CleanLayer CleanLayerOf(const proto::CleanedMap& cleaned, const proto::GridMap* grid) {
  CheckCells(cleaned.cells(), cleaned.frame());
  const int64_t cell_count = static_cast<int64_t>(cleaned.cells().size());
  cv::Mat image(cleaned.frame().height_px(), cleaned.frame().width_px(), CV_8UC1,
                cv::Scalar(viewer::CLEAN_UNCHANGED));
  auto mark = [&](int64_t cell, viewer::CleanChange change) {
    if (cell >= 0 && cell < cell_count) image.data[cell] = static_cast<uint8_t>(change);
  };
  viewer::CleanLayer layer;
  if (grid != nullptr && grid->cells().size() == cleaned.cells().size()) {
    int freed = 0;
    for (int64_t i = 0; i < cell_count; ++i) {
      if (grid->cells()[i] == proto::CELL_UNKNOWN && cleaned.cells()[i] == proto::CELL_FREE) {
        mark(i, viewer::CLEAN_FREED_UNKNOWN);
        ++freed;
      }
    }
    layer.set_freed_unknown_cells(freed);
  }
  for (const int cell : cleaned.removed_outlier_cells()) mark(cell, viewer::CLEAN_OUTLIER);
  for (const int cell : cleaned.removed_furniture_cells()) mark(cell, viewer::CLEAN_FURNITURE);
  layer.set_changes_png(EncodePng(image));
  std::string outlines;
  for (const proto::Polygon& shape : cleaned.furniture_shapes()) outlines += PolygonPath(shape);
  layer.set_furniture_outlines(outlines);
  layer.set_outlier_cells(cleaned.removed_outlier_cells_size());
  layer.set_furniture_cells(cleaned.removed_furniture_cells_size());
  return layer;
}

}  // namespace areagraph

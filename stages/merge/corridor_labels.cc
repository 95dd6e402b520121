#include "stages/merge/corridor_labels.h"

#include <algorithm>
#include <cstdint>
#include <opencv2/imgproc.hpp>
#include <vector>

#include "stages/geometry/distance_transform.h"
#include "stages/geometry/region_boxes.h"

namespace areagraph {

namespace {

// The shape of the non-zero cells of `mask` (CV_8U, a margin of zeros all
// round), with holes filled. Changes `mask`.
AreaShape ShapeOfMask(cv::Mat& mask) {
  FillHoles(&mask);
  // Only the deepest cell counts: no distance image.
  const double deepest = DeepestDistance(mask);
  return {2 * deepest, static_cast<double>(cv::countNonZero(mask))};
}

AreaShape ShapeOfArea(const AreaRaster& raster, int k, const cv::Rect& box) {
  if (box.area() == 0) return {};
  cv::Mat mask = LabelMaskInBox(raster.labels, k + 1, box);
  return ShapeOfMask(mask);
}

}  // namespace

void FillHoles(cv::Mat* mask) {
  CV_Assert(mask->type() == CV_8U);
  const int rows = mask->rows, cols = mask->cols;
  // The zero cells' runs, row by row.
  std::vector<PieceRun> runs;
  std::vector<size_t> row_start{0};
  for (int r = 0; r < rows; ++r) {
    const uint8_t* row = mask->ptr<uint8_t>(r);
    for (int c = 0; c < cols;) {
      if (row[c] != 0) {
        ++c;
        continue;
      }
      const int begin = c;
      while (c < cols && row[c] == 0) ++c;
      runs.push_back({r, begin, c, 0});
    }
    row_start.push_back(runs.size());
  }
  int count = 0;
  const std::vector<int> piece = JoinRowRuns(
      runs, row_start, /*eight_connected=*/false,
      [](const PieceRun&, const PieceRun&) { return true; }, &count);
  std::vector<uint8_t> open(count, 0);
  for (size_t i = 0; i < runs.size(); ++i) {
    const PieceRun& run = runs[i];
    if (run.row == 0 || run.row == rows - 1 || run.begin == 0 || run.end == cols) {
      open[piece[i]] = 1;
    }
  }
  for (size_t i = 0; i < runs.size(); ++i) {
    if (open[piece[i]]) continue;
    uint8_t* row = mask->ptr<uint8_t>(runs[i].row);
    std::fill(row + runs[i].begin, row + runs[i].end, 255);
  }
}

std::vector<AreaShape> AreaShapes(const AreaRaster& raster) {
  std::vector<AreaShape> shapes;
  for (size_t k = 0; k < raster.boxes.size(); ++k) {
    shapes.push_back(ShapeOfArea(raster, static_cast<int>(k), raster.boxes[k]));
  }
  return shapes;
}

bool IsCorridorShaped(const AreaShape& shape, double resolution_m) {
  return shape.width_px > 0 && shape.width_px <= kMaxCorridorWidthM / resolution_m &&
         shape.area_px >= kMinCorridorElongation * shape.width_px * shape.width_px;
}

void LabelCorridorsByShape(const AreaRaster& raster, double resolution_m, AreaPlan* plan) {
  // Only rooms change: the other areas' shapes (a distance transform each) are not measured.
  for (size_t k = 0; k < plan->areas.size() && k < raster.boxes.size(); ++k) {
    AreaPlan::Area& area = plan->areas[k];
    if (area.kind == proto::AREA_ROOM &&
        IsCorridorShaped(ShapeOfArea(raster, static_cast<int>(k), raster.boxes[k]), resolution_m)) {
      area.kind = proto::AREA_CORRIDOR;
    }
  }
}

}  // namespace areagraph

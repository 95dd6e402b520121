#include "stages/merge/corridor_labels.h"

#include <limits>
#include <opencv2/imgproc.hpp>
#include <vector>

#include "stages/geometry/distance_transform.h"
#include "stages/geometry/enclosed_pockets.h"
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
  // The holes are the enclosed pockets of any size.
  FillEnclosedPockets(std::numeric_limits<double>::infinity(), mask);
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

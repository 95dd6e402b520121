#include "stages/merge/corridor_labels.h"

#include <algorithm>
#include <cstdint>
#include <limits>
#include <opencv2/imgproc.hpp>
#include <vector>

#include "stages/geometry/distance_transform.h"
#include "stages/geometry/enclosed_pockets.h"
#include "stages/geometry/parallel_ranges.h"
#include "stages/geometry/region_boxes.h"

namespace areagraph {

namespace {

// At least this many box cells per parallel range of rooms: a smaller range
// costs more to start than it gains.
constexpr int64_t kMinRangeBoxCells = int64_t(1) << 17;

// Calls body(begin, end) for contiguous ranges of items, in parallel, each
// range holding about the same weight: `before[i]` is the weight of the
// items before item i (before.size() is the item count + 1).
template <typename Body>
void ForEachWeightedRange(const std::vector<int64_t>& before, int64_t min_weight,
                          const Body& body) {
  const size_t items = before.size() - 1;
  const int64_t total = before.back();
  const int ranges = ParallelRangeCount(static_cast<size_t>(total), min_weight);
  // Range i: the items whose weight starts in [total * i, total * (i + 1)) / ranges.
  auto first_at = [&](int i) {
    const size_t weight = ParallelRangeBegin(static_cast<size_t>(total), ranges, i);
    return static_cast<size_t>(
        std::lower_bound(before.begin(), before.end() - 1, static_cast<int64_t>(weight)) -
        before.begin());
  };
  ForEachRange(static_cast<size_t>(ranges), ranges, [&](size_t range, size_t, int) {
    const size_t begin = first_at(static_cast<int>(range));
    const size_t end =
        range + 1 == static_cast<size_t>(ranges) ? items : first_at(static_cast<int>(range) + 1);
    if (begin < end) body(begin, end);
  });
}

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
  // Only rooms change: the other areas' shapes (a distance transform each)
  // are not measured. Each room's on its own, in parallel ranges of about
  // equal box cells; the kinds change after all are measured.
  std::vector<int> rooms;
  std::vector<int64_t> cells_before{0};
  for (size_t k = 0; k < plan->areas.size() && k < raster.boxes.size(); ++k) {
    if (plan->areas[k].kind != proto::AREA_ROOM) continue;
    rooms.push_back(static_cast<int>(k));
    cells_before.push_back(cells_before.back() + raster.boxes[k].area() + 1);
  }
  std::vector<uint8_t> corridor(rooms.size(), 0);
  ForEachWeightedRange(cells_before, kMinRangeBoxCells, [&](size_t begin, size_t end) {
    for (size_t i = begin; i < end; ++i) {
      const int k = rooms[i];
      corridor[i] = IsCorridorShaped(ShapeOfArea(raster, k, raster.boxes[k]), resolution_m);
    }
  });
  for (size_t i = 0; i < rooms.size(); ++i) {
    if (corridor[i]) plan->areas[rooms[i]].kind = proto::AREA_CORRIDOR;
  }
}

}  // namespace areagraph

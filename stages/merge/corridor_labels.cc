#include "stages/merge/corridor_labels.h"

#include <algorithm>
#include <cstdint>
#include <limits>
#include <opencv2/imgproc.hpp>
#include <thread>
#include <vector>

#include "stages/geometry/distance_transform.h"
#include "stages/geometry/enclosed_pockets.h"
#include "stages/geometry/parallel_ranges.h"
#include "stages/geometry/region_boxes.h"
#include "stages/merge/deepest_bound.h"

namespace areagraph {

namespace {

// At least this many box cells per thread that shares the rooms: fewer
// cost more to start a thread than they gain.
constexpr int64_t kMinRangeBoxCells = int64_t(1) << 17;

// Area k's cells in `box`, with a margin of zeros all round and holes filled.
cv::Mat FilledAreaMask(const AreaRaster& raster, int k, const cv::Rect& box) {
  cv::Mat mask = LabelMaskInBox(raster.labels, k + 1, box);
  FillHoles(&mask);
  return mask;
}

// The shape of the non-zero cells of a FilledAreaMask.
AreaShape ShapeOfFilledMask(const cv::Mat& mask) {
  // Only the deepest cell counts: no distance image.
  const double deepest = DeepestDistance(mask);
  return {2 * deepest, static_cast<double>(cv::countNonZero(mask))};
}

AreaShape ShapeOfArea(const AreaRaster& raster, int k, const cv::Rect& box) {
  if (box.area() == 0) return {};
  return ShapeOfFilledMask(FilledAreaMask(raster, k, box));
}

// Whether area k of `raster` is corridor-shaped: IsCorridorShaped of its
// ShapeOfArea. Where DeepestDistance would take OpenCV's single precision
// (boxes over 4096 cells, the rows of lab_a tiled 8 x 8 joined into one
// room), a lower bound of it decides first when it can: too wide or too
// short for a corridor stays so for every larger width.
bool AreaIsCorridorShaped(const AreaRaster& raster, int k, const cv::Rect& box,
                          double resolution_m) {
  if (box.area() == 0) return IsCorridorShaped({}, resolution_m);
  const cv::Mat mask = FilledAreaMask(raster, k, box);
  if (!ComputedExactly(mask.size())) {
    const double least_width_px = 2 * DeepestDistanceLowerBound(mask);
    const double area_px = static_cast<double>(cv::countNonZero(mask));
    if (least_width_px > 0 && !IsCorridorShaped({least_width_px, area_px}, resolution_m)) {
      return false;
    }
  }
  return IsCorridorShaped(ShapeOfFilledMask(mask), resolution_m);
}

// The room areas of `plan` that `raster` has a box for, in area order.
std::vector<int> RoomsOf(const AreaRaster& raster, const AreaPlan& plan) {
  std::vector<int> rooms;
  for (size_t k = 0; k < plan.areas.size() && k < raster.boxes.size(); ++k) {
    if (plan.areas[k].kind == proto::AREA_ROOM) rooms.push_back(static_cast<int>(k));
  }
  return rooms;
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
  // are not measured. The pool's threads share the rooms when their boxes
  // hold enough cells for it.
  CorridorShapeWork work(raster, resolution_m, *plan);
  const int threads =
      std::min(cv::getNumThreads(),
               ParallelRangeCount(static_cast<size_t>(work.box_cells()), kMinRangeBoxCells));
  ForEachRange(static_cast<size_t>(threads), threads, [&](size_t, size_t, int) { work.Measure(); });
  work.Finish();
  work.Apply(plan);
}

CorridorShapeWork::CorridorShapeWork(const AreaRaster& raster, double resolution_m,
                                     const AreaPlan& plan)
    : raster_(raster), resolution_m_(resolution_m), rooms_(RoomsOf(raster, plan)) {
  for (const int k : rooms_) box_cells_ += raster.boxes[k].area() + 1;
  // Biggest first, so that no thread is left with a big room at the end.
  std::stable_sort(rooms_.begin(), rooms_.end(),
                   [&](int a, int b) { return raster.boxes[a].area() > raster.boxes[b].area(); });
  corridor_.assign(rooms_.size(), 0);
}

void CorridorShapeWork::Measure() {
  for (size_t i = next_++; i < rooms_.size(); i = next_++) {
    try {
      const int k = rooms_[i];
      corridor_[i] = AreaIsCorridorShaped(raster_, k, raster_.boxes[k], resolution_m_);
    } catch (...) {
      const std::lock_guard<std::mutex> lock(error_mutex_);
      if (!error_) error_ = std::current_exception();
    }
    done_.fetch_add(1, std::memory_order_release);
  }
}

void CorridorShapeWork::Finish() {
  Measure();
  // The rooms still being measured are on threads that are running.
  while (done_.load(std::memory_order_acquire) < rooms_.size()) std::this_thread::yield();
  if (error_) std::rethrow_exception(error_);
}

void CorridorShapeWork::Apply(AreaPlan* plan) const {
  for (size_t i = 0; i < rooms_.size(); ++i) {
    if (corridor_[i]) plan->areas[rooms_[i]].kind = proto::AREA_CORRIDOR;
  }
}

}  // namespace areagraph

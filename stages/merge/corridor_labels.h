#pragma once

#include <atomic>
#include <cstdint>
#include <exception>
#include <mutex>
#include <vector>

#include "stages/merge/area_assignment.h"
#include "stages/merge/area_raster.h"

namespace areagraph {

// A corridor is at most this wide (metres): "an indoor corridor is hardly
// wider than 4 m" (the paper, on the range of W); wider areas are halls.
inline constexpr double kMaxCorridorWidthM = 4.0;
// A corridor is at least this many times as long as it is wide: its area is
// at least this many squares of its width. Rooms and halls are squarer.
inline constexpr double kMinCorridorElongation = 4.0;

// The shape of an area: the width of its widest free disk and its area, both
// measured with its holes (furniture, pillars) filled.
struct AreaShape {
  double width_px = 0;
  double area_px = 0;
};

// Sets to 255 the zero cells of `mask` (CV_8U, a margin of zeros all round)
// that no 4-connected path of zero cells joins to the mask's border: the
// non-zero cells' holes. What filling the outer contours of the non-zero
// cells (cv::findContours, cv::drawContours) paints, found over the rows' runs.
void FillHoles(cv::Mat* mask);

// The shape of every area of `raster` (zero for an area without cells).
std::vector<AreaShape> AreaShapes(const AreaRaster& raster);

// Whether a shape is a corridor's (see LabelCorridorsByShape).
bool IsCorridorShaped(const AreaShape& shape, double resolution_m);

// Relabels room areas shaped like corridors as corridors: long (area at least
// kMinCorridorElongation squares of the width) and at most kMaxCorridorWidthM
// wide. The room disk makes every area it fits in a room, so a corridor
// wider than W came out as a room; its length tells it apart. Dead ends and
// corridors keep their kind.
void LabelCorridorsByShape(const AreaRaster& raster, double resolution_m, AreaPlan* plan);

// LabelCorridorsByShape in steps that threads share, so that the rooms are
// measured beside other work on the same raster: Measure, from any thread,
// measures rooms until none is left unclaimed (biggest box first); Finish
// measures what is left, waits for the rooms other threads are measuring and
// rethrows the first error, after which the raster's labels are read no more;
// Apply then sets the kinds. Each room's result has its own slot, so which
// thread measured it does not matter.
class CorridorShapeWork {
 public:
  CorridorShapeWork(const AreaRaster& raster, double resolution_m, const AreaPlan& plan);
  CorridorShapeWork(const CorridorShapeWork&) = delete;
  CorridorShapeWork& operator=(const CorridorShapeWork&) = delete;

  void Measure();
  void Finish();
  void Apply(AreaPlan* plan) const;
  // The rooms' box cells (plus one a room): how much there is to measure.
  int64_t box_cells() const { return box_cells_; }

 private:
  const AreaRaster& raster_;
  const double resolution_m_;
  std::vector<int> rooms_;
  std::vector<uint8_t> corridor_;
  int64_t box_cells_ = 0;
  std::atomic<size_t> next_{0};
  std::atomic<size_t> done_{0};
  std::mutex error_mutex_;
  std::exception_ptr error_;
};

}  // namespace areagraph

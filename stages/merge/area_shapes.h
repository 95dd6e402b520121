#pragma once

#include <vector>

#include "proto/artifacts.pb.h"
#include "stages/merge/area_assignment.h"
#include "stages/merge/area_moments.h"
#include "stages/merge/area_raster.h"

namespace areagraph {

// The shape of one area, what the merge passes and the areas' kinds read:
// its width profile (the free width along its middle), its size and which
// way it runs, with one definition of a corridor
// (stages/geometry/corridor_shape.h).
struct AreaShape {
  // The width profile's median and maximum (px).
  double typical_px = 0;
  double widest_px = 0;
  // Its size (px).
  double area_px = 0;
  // IsCorridorShaped.
  bool corridor = false;
  // Where it lies and which way it runs (candidate areas only, see
  // MeasureAreaShapes).
  AreaMoments moments;

  // How many squares of its typical width it covers.
  double Elongation() const;
  // How straight it runs: its major axis' variance over its minor axis' (1
  // for a square or a disk, 0 without moments).
  double Straightness() const;
};

// The shapes of every candidate area of `plan` (before the free space is
// split), from the CutGraph: the width profile is the clearance along its
// edges (twice each sample), its size its edges' polygons and what they
// absorbed, its moments those of its edges' outer rings.
std::vector<AreaShape> MeasureAreaShapes(const proto::CutGraph& graph, const AreaPlan& plan,
                                         double resolution_m);

// The shape of area k of the split free space (no moments): its cells with
// the holes of a furniture island's size (at most `island_max_m` long,
// CutGraph.island_max_length_m, furniture_islands.h) filled, so
// that desks and pillars do not narrow it while the block of rooms inside a
// corridor loop stays out; the width profile is twice the distance to its
// outline along its ridge (the cells at least as deep as their neighbours).
// Cells where `furniture` (CV_8U, map size, optional) is non-zero count as
// the area's too within its box: rows of seats (FurnitureRowCells) are
// longer than an island, and the strips between them no corridor.
AreaShape RasterShape(const AreaRaster& raster, int k, double resolution_m, double island_max_m,
                      const cv::Mat& furniture = cv::Mat());

}  // namespace areagraph

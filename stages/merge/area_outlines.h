#pragma once

#include <functional>
#include <opencv2/core.hpp>
#include <vector>

#include "stages/merge/planar_partition.h"

namespace areagraph {

// An area's polygon in pixel coordinates: the outer ring clockwise on screen
// (positive SignedArea), holes the other way.
struct AreaOutline {
  PointList outer;
  std::vector<PointList> holes;
};

// The polygons of a planar partition after hole removal and simplification.
struct PartitionOutlines {
  // Per area (label - 1); empty for a label without cells.
  std::vector<AreaOutline> areas;
  // Every chain's points after simplification, by chain index; empty for
  // the chains of dropped holes. Both areas along a chain hold exactly these
  // points.
  std::vector<PointList> chains;
  // Holes dropped for being smaller than the minimum.
  int dropped_holes = 0;
};

// The outlines of the areas of `partition` (traced from `labels`). A hole
// smaller than `min_hole_px2` square pixels that holds no other area (an
// obstacle or unlabelled speck inside the area) is dropped, so the area
// covers it. Then all remaining borders are simplified together
// (SimplifyBorders with `tolerance_px`), so neighbours keep sharing their
// borders and junctions, and no two borders cross. A kept hole that this
// could shrink below the minimum (a thin obstacle) is simplified within half
// a cell instead, or not at all. `labels_done`, when given, is called once
// `labels` is read no more (before the simplification, which takes memory of
// its own), so that the caller may free the raster.
PartitionOutlines SimplifiedOutlines(const PlanarPartition& partition, const cv::Mat& labels,
                                     double tolerance_px, double min_hole_px2,
                                     const std::function<void()>& labels_done = {});

}  // namespace areagraph

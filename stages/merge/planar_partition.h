#pragma once

#include <opencv2/core.hpp>
#include <vector>

#include "stages/geometry/edge_polygon.h"

namespace areagraph {

// One border of the planar partition of a label image: the cell edges
// between two regions, from one junction to another, stored once for both
// sides so that neighbours share it vertex for vertex.
struct BorderChain {
  // Pixel coordinates (cell (c, r) spans [c, c+1] x [r, r+1]), no point on
  // the straight line through its two neighbours. The first and last points
  // are where three or more regions meet, or (for a border that is a closed
  // loop, cut into three chains) points picked on the loop's hull.
  PointList points;
  // The regions on either side walking from the first point to the last
  // (right and left on screen, y down); 0 is no area.
  int right = 0;
  int left = 0;
};

// A chain walked forwards (its `right` region on the right) or backwards.
struct ChainSide {
  int chain = -1;
  bool reversed = false;
};

// A label image (CV_32S: 0 no area, 1..label_count areas; outside the image
// is 0) as a planar map. Cells that touch only at a corner are joined there
// when they are no area (a diagonal wall stays closed) and kept apart when
// they are one area (its ring stays simple: the corner is cut by 0.05 px);
// areas are expected to be 4-connected.
struct PlanarPartition {
  std::vector<BorderChain> chains;
  // rings[label - 1]: the closed borders of each area, each a cycle of chain
  // sides that keep the area on the right: the outer ring runs clockwise on
  // screen (positive SignedArea) and holes the other way.
  std::vector<std::vector<std::vector<ChainSide>>> rings;
};

// Traces every border of `labels` once.
PlanarPartition BuildPlanarPartition(const cv::Mat& labels, int label_count);

// The points of `ring` with every chain's points taken from `chain_points`
// (the chains themselves, or their simplified versions), each point once.
PointList RingPoints(const std::vector<ChainSide>& ring,
                     const std::vector<PointList>& chain_points);

// The chains' points, in chain order.
std::vector<PointList> ChainPoints(const PlanarPartition& partition);

}  // namespace areagraph

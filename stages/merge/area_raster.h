#pragma once

#include <cstdint>
#include <opencv2/core.hpp>
#include <vector>

#include "proto/geometry.pb.h"
#include "stages/geometry/cell_grid.h"
#include "stages/geometry/edge_polygon.h"

namespace areagraph {

// The map's free cells split among the areas: `labels` (CV_32S, map size)
// holds 0 for no area and k + 1 for area k.
struct AreaRaster {
  cv::Mat labels;
  // Cells of each area.
  std::vector<int64_t> cell_count;
  // The bounding box of each area's cells (empty for an area without cells).
  std::vector<cv::Rect> boxes;
  // Free cells inside the boundary: what the areas should cover.
  int64_t domain_cells = 0;
};

// Paints every area's polygons (area_polygons[k] for area k) on the free
// cells inside the boundaries (`boundary_mask`, CV_8U, map size, see
// BoundaryMask), then the paths of its edges on top (so that areas
// that share a graph vertex touch there), grows the labels into the remaining such cells
// (breadth first, 4-connected), keeps only the main 4-connected piece of
// each area (the one with most of its paths, else the biggest) and grows again, so that every area
// is one connected piece and no two overlap. `through_paths` (path, area) are painted last: the
// paths of an area that runs through a graph vertex (it has several edges there), which a
// neighbour's path through the same cells would otherwise cut apart.
//
// With `min_gap_px` > 0 the growth does not pass gaps narrower than that:
// the free cells at least min_gap_px / 2 from every non-free cell form
// cores, split at such gaps; a core of at least (2 min_gap_px)^2 cells that
// no area's polygons or paths touch is free space the graph never reached
// (a room behind a door too narrow for the Topology Graph), and it claims,
// competing in the same growth, the cells nearer to it, which then stay
// unlabelled.
//
// Cells where `keep_out` (CV_8U, map size, optional) is non-zero are not
// part of the domain: no area covers them.
//
// `boundary_mask` is taken by value so that a caller that hands it over
// (std::move or a temporary) lends its buffer to the domain raster: on a big
// map every raster of the map's size counts towards the peak memory.
AreaRaster PartitionFreeSpace(const CellGrid& grid, cv::Mat boundary_mask,
                              const std::vector<std::vector<const proto::Polygon*>>& area_polygons,
                              const std::vector<std::vector<PointList>>& area_paths,
                              const std::vector<std::pair<PointList, int>>& through_paths,
                              double min_gap_px = 0, const cv::Mat& keep_out = cv::Mat());

// Sets `cell_count` and `boxes` from the labels, for as many areas as
// `cell_count` has (one pass over the rows' runs).
void CountAreaCells(AreaRaster* raster);

}  // namespace areagraph

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
  // Free cells inside the boundary: what the areas should cover.
  int64_t domain_cells = 0;
};

// Paints every area's polygons (area_polygons[k] for area k) on the free
// cells inside `boundary`, then the paths of its edges on top (so that areas
// that share a graph vertex touch there), grows the labels into the remaining such cells
// (breadth first, 4-connected), keeps only the main 4-connected piece of
// each area (the one with most of its paths, else the biggest) and grows again, so that every area
// is one connected piece and no two overlap. `through_paths` (path, area) are painted last: the
// paths of an area that runs through a graph vertex (it has several edges there), which a
// neighbour's path through the same cells would otherwise cut apart.
AreaRaster PartitionFreeSpace(const CellGrid& grid, const proto::Polygon& boundary,
                              const std::vector<std::vector<const proto::Polygon*>>& area_polygons,
                              const std::vector<std::vector<PointList>>& area_paths,
                              const std::vector<std::pair<PointList, int>>& through_paths);

// Gives the cells of area `from` to area `into` and drops `from` (later
// areas' labels shift down by one).
void MergeAreaCells(int from, int into, AreaRaster* raster);

// How many cell sides area a shares with area b, for every touching pair
// (a < b), keyed a * area_count + b.
std::vector<std::pair<int64_t, int64_t>> SharedBorders(const AreaRaster& raster);

}  // namespace areagraph

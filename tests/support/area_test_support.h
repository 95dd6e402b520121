#pragma once

#include <opencv2/core.hpp>
#include <string>

#include "proto/artifacts.pb.h"
#include "proto/pipeline_options.pb.h"
#include "stages/merge/area_raster.h"

namespace areagraph::testing {

// A CleanedMap from an 8-bit drawing (0 wall, 254 free, 205 unknown; darker
// than 100 is a wall, 250 and lighter free), origin at (0, 0).
proto::CleanedMap CleanedMapFromImage(const cv::Mat& grey, double resolution_m = 0.05);

// The same drawing run through ag-clean (outlier and furniture removal) with
// `options`, as the pipeline sees it.
proto::CleanedMap CleanDrawnMap(const cv::Mat& grey, const proto::CleanOptions& options = {},
                                double resolution_m = 0.05);

// Everything the area stages make for one map.
struct AreaStages {
  // The options they ran with.
  proto::PipelineOptions options;
  proto::VoronoiDiagram diagram;
  proto::TopologyGraph topology;
  proto::CutGraph cut;
  proto::AreaGraph areas;
  AreaRaster raster;
};

// Runs ag-voronoi, ag-prune, ag-cut and ag-merge in process.
AreaStages RunAreaStages(const proto::CleanedMap& map, const proto::PipelineOptions& options = {},
                         const std::string& map_name = "test");

// Checks what every Area Graph must satisfy (gtest failures, not exceptions):
// - every area polygon is simple (CGAL is_simple_2 per ring, and no ring
//   touches another), with positive area;
// - no cell centre lies inside two area polygons, and the raster labels one
//   area per cell;
// - the areas cover at least `min_coverage` of the free cells inside the
//   boundary, in the raster and in the polygons, and at least 99 % of those
//   that are reachable (4-connected through free cells inside the boundary)
//   from some area: real maps have closed-off pockets, such as courtyards,
//   and rooms behind gaps narrower than merge.grow_min_gap_m that no area
//   reached do not count;
// - every passage joins two different existing areas, and both have cells
//   next to the passage point;
// - the areas are connected through the passages;
// - every CutGraph edge belongs to exactly one area.
void ExpectAreaGraphInvariants(const AreaStages& stages, const proto::CleanedMap& map,
                               double min_coverage = 0.95);

// Id of the area whose polygon holds the point given in plan metres (x
// right, y down from the top-left corner, like floorplan::RectM), or -1.
int AreaAt(const proto::AreaGraph& graph, double x_m, double y_m, double resolution_m = 0.05);

}  // namespace areagraph::testing

#pragma once

#include <opencv2/core.hpp>
#include <string>

#include "proto/artifacts.pb.h"
#include "proto/pipeline_options.pb.h"
#include "stages/merge/area_raster.h"
#include "tools/example_maps/floor_plan.h"

namespace areagraph::testing {

// A CleanedMap from an 8-bit drawing (0 wall, 254 free, 205 unknown; darker
// than 100 is a wall, 250 and lighter free), origin at (0, 0).
proto::CleanedMap CleanedMapFromImage(const cv::Mat& grey, double resolution_m = 0.05);

// A CleanedMap of cell states (CV_8U, proto::CellState values), origin at (0, 0).
proto::CleanedMap CleanedMapOfCells(const cv::Mat& cells, double resolution_m = 0.05);

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
AreaStages RunAreaStages(const proto::CleanedMap& map, const proto::PipelineOptions& options = {});

// Checks what every Area Graph must satisfy (gtest failures, not exceptions):
// - every area polygon is simple (CGAL is_simple_2 per ring, and no ring
//   touches another), with positive area;
// - no cell centre lies inside two area polygons, no two polygons' interiors
//   overlap (exact), and a cell that a polygon other than its raster area's
//   holds lies within merge.outline_tolerance_m (plus a cell) of that area;
// - the areas cover at least `min_coverage` of the free cells inside the
//   boundary, in the raster and in the polygons, and at least 99 % of those
//   that are reachable (4-connected through free cells inside the boundary)
//   from some area: real maps have closed-off pockets, such as courtyards,
//   and rooms behind gaps narrower than the robot's width that no area
//   reached do not count;
// - every passage joins two different existing areas, both have cells next
//   to the passage point, and its end points are vertices of both areas'
//   outlines (a piece of their shared border);
// - the areas are connected through the passages into AreaGraph.components
//   components, no more than the parts of the map that prune kept;
// - every CutGraph edge belongs to exactly one area.
void ExpectAreaGraphInvariants(const AreaStages& stages, const proto::CleanedMap& map,
                               double min_coverage = 0.95);

// Drawn maps that several merge tests share.
// Two rooms (4 and 4.5 m wide, 4 m deep) joined by a 0.9 m door centred at
// (4.5, 2.5) m in the wall between them.
floorplan::FloorPlan TwoRoomsWithADoor();
// An L-shaped corridor, 1.0 m free between its walls.
floorplan::FloorPlan LCorridor();
// A 5 x 5 maze of 1.15 m cells with 0.15 m walls: corridors 1.0 m wide.
floorplan::FloorPlan FiveByFiveMaze();
// The paper's areas on the maze: a fixed W of 2 m (no room shapes), every
// area kept however small, one area per Topology Graph edge.
proto::PipelineOptions PaperMazeOptions();

// Id of the area whose polygon holds the point given in plan metres (x
// right, y down from the top-left corner, like floorplan::RectM), or -1.
int AreaAt(const proto::AreaGraph& graph, double x_m, double y_m, double resolution_m = 0.05);

}  // namespace areagraph::testing

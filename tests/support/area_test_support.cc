#include "tests/support/area_test_support.h"

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Polygon_2.h>
#include <gtest/gtest.h>

#include <cmath>
#include <deque>
#include <opencv2/imgproc.hpp>
#include <set>

#include "stages/clean/clean_stage.h"
#include "stages/common/map_frame.h"
#include "stages/common/skipped_passes.h"
#include "stages/cut/cut_graph_builder.h"
#include "stages/geometry/edge_polygon.h"
#include "stages/geometry/polygon_raster.h"
#include "stages/geometry/ring_simplicity.h"
#include "stages/merge/area_graph_builder.h"
#include "stages/prune/topology_graph_builder.h"
#include "stages/voronoi/voronoi_stage.h"
#include "tools/bench/area_graph_checks.h"

namespace areagraph::testing {
namespace {

using Kernel = CGAL::Exact_predicates_exact_constructions_kernel;

bool CgalSimple(const proto::Ring& ring) {
  CGAL::Polygon_2<Kernel> polygon;
  for (const proto::Point2& p : ring.points()) polygon.push_back(Kernel::Point_2(p.x(), p.y()));
  return polygon.size() >= 3 && polygon.is_simple();
}

// Even-odd test of a point against a polygon with holes.
bool Inside(const proto::Polygon& polygon, double x, double y) {
  bool inside = false;
  auto cross_ring = [&](const proto::Ring& ring) {
    const int n = ring.points_size();
    for (int i = 0, j = n - 1; i < n; j = i++) {
      const proto::Point2& a = ring.points(i);
      const proto::Point2& b = ring.points(j);
      if ((a.y() > y) != (b.y() > y) &&
          x < (b.x() - a.x()) * (y - a.y()) / (b.y() - a.y()) + a.x()) {
        inside = !inside;
      }
    }
  };
  cross_ring(polygon.outer());
  for (const proto::Ring& hole : polygon.holes()) cross_ring(hole);
  return inside;
}

cv::Rect Bounds(const proto::Ring& ring, cv::Size size) {
  double x0 = 1e18, y0 = 1e18, x1 = -1e18, y1 = -1e18;
  for (const proto::Point2& p : ring.points()) {
    x0 = std::min(x0, p.x()), y0 = std::min(y0, p.y());
    x1 = std::max(x1, p.x()), y1 = std::max(y1, p.y());
  }
  const cv::Rect box(static_cast<int>(std::floor(x0)) - 1, static_cast<int>(std::floor(y0)) - 1,
                     static_cast<int>(x1 - x0) + 3, static_cast<int>(y1 - y0) + 3);
  return box & cv::Rect(0, 0, size.width, size.height);
}

// Cells of the cores (free cells at least min_gap_px / 2 from every
// non-free cell, in 4-connected pieces of at least (2 min_gap_px)^2 cells)
// that hold no labelled cell, widened by min_gap_px / 2: free space behind a
// gap narrower than min_gap_px that no area reached. Empty for min_gap_px 0.
cv::Mat UnreachedRooms(const AreaRaster& raster, const proto::CleanedMap& map, double min_gap_px) {
  const cv::Size size = raster.labels.size();
  cv::Mat unreached = cv::Mat::zeros(size, CV_8U);
  if (min_gap_px <= 0) return unreached;
  cv::Mat free_cells(size, CV_8U);
  for (int r = 0; r < size.height; ++r) {
    for (int c = 0; c < size.width; ++c) {
      free_cells.at<uint8_t>(r, c) =
          map.cells()[static_cast<size_t>(r) * size.width + c] == proto::CELL_FREE ? 255 : 0;
    }
  }
  cv::Mat distance, pieces;
  cv::distanceTransform(free_cells, distance, cv::DIST_L2, cv::DIST_MASK_PRECISE);
  const int count = cv::connectedComponents(distance >= 0.5 * min_gap_px, pieces, 4, CV_32S);
  std::vector<int64_t> cells(count, 0);
  std::vector<bool> labelled(count, false);
  for (int r = 0; r < size.height; ++r) {
    for (int c = 0; c < size.width; ++c) {
      const int piece = pieces.at<int>(r, c);
      ++cells[piece];
      if (raster.labels.at<int>(r, c) > 0) labelled[piece] = true;
    }
  }
  for (int r = 0; r < size.height; ++r) {
    for (int c = 0; c < size.width; ++c) {
      const int piece = pieces.at<int>(r, c);
      if (piece > 0 && !labelled[piece] && cells[piece] >= 4 * min_gap_px * min_gap_px) {
        unreached.at<uint8_t>(r, c) = 255;
      }
    }
  }
  const int reach = static_cast<int>(std::ceil(0.5 * min_gap_px));
  cv::dilate(unreached, unreached,
             cv::getStructuringElement(cv::MORPH_ELLIPSE, cv::Size(2 * reach + 1, 2 * reach + 1)));
  return unreached;
}

// Free cells inside the boundary that are 4-connected (through such cells,
// outside UnreachedRooms) to a labelled cell, those included.
int64_t ReachableCells(const AreaRaster& raster, const proto::CleanedMap& map,
                       const proto::CutGraph& cut, double min_gap_px) {
  const cv::Size size = raster.labels.size();
  const cv::Mat inside = BoundaryMask(cut.part_boundaries(), cut.boundary(), size);
  const cv::Mat unreached = UnreachedRooms(raster, map, min_gap_px);
  cv::Mat seen = cv::Mat::zeros(size, CV_8U);
  std::deque<cv::Point> queue;
  for (int r = 0; r < size.height; ++r) {
    for (int c = 0; c < size.width; ++c) {
      if (raster.labels.at<int>(r, c) > 0) seen.at<uint8_t>(r, c) = 1, queue.emplace_back(c, r);
    }
  }
  int64_t reached = 0;
  const int dx[4] = {1, -1, 0, 0}, dy[4] = {0, 0, 1, -1};
  while (!queue.empty()) {
    const cv::Point p = queue.front();
    queue.pop_front();
    ++reached;
    for (int k = 0; k < 4; ++k) {
      const cv::Point q(p.x + dx[k], p.y + dy[k]);
      if (q.x < 0 || q.y < 0 || q.x >= size.width || q.y >= size.height || seen.at<uint8_t>(q)) {
        continue;
      }
      if (map.cells()[static_cast<size_t>(q.y) * size.width + q.x] != proto::CELL_FREE ||
          !inside.at<uint8_t>(q) || unreached.at<uint8_t>(q)) {
        continue;
      }
      seen.at<uint8_t>(q) = 1;
      queue.push_back(q);
    }
  }
  return reached;
}

}  // namespace

proto::CleanedMap CleanedMapOfCells(const cv::Mat& cells, double resolution_m) {
  CV_Assert(cells.type() == CV_8U && cells.isContinuous());
  proto::CleanedMap map;
  map.mutable_frame()->set_width_px(cells.cols);
  map.mutable_frame()->set_height_px(cells.rows);
  map.mutable_frame()->set_resolution_m(resolution_m);
  map.set_cells(std::string(cells.datastart, cells.dataend));
  // As ag-clean writes it with the default options.
  map.set_robot_width_m(proto::CleanOptions().robot_width_m());
  return map;
}

proto::CleanedMap CleanedMapFromImage(const cv::Mat& grey, double resolution_m) {
  proto::CleanedMap map;
  map.set_format_version(1);
  proto::MapFrame* frame = map.mutable_frame();
  frame->set_resolution_m(resolution_m);
  frame->set_width_px(grey.cols);
  frame->set_height_px(grey.rows);
  std::string cells(static_cast<size_t>(grey.cols) * grey.rows, '\0');
  for (int r = 0; r < grey.rows; ++r) {
    for (int c = 0; c < grey.cols; ++c) {
      const int value = grey.at<uint8_t>(r, c);
      cells[static_cast<size_t>(r) * grey.cols + c] =
          static_cast<char>(value <= 100 ? proto::CELL_OCCUPIED
                                         : (value >= 250 ? proto::CELL_FREE : proto::CELL_UNKNOWN));
    }
  }
  map.set_cells(cells);
  map.set_robot_width_m(proto::CleanOptions().robot_width_m());
  return map;
}

proto::CleanedMap CleanDrawnMap(const cv::Mat& grey, const proto::CleanOptions& options,
                                double resolution_m) {
  const proto::CleanedMap drawn = CleanedMapFromImage(grey, resolution_m);
  proto::GridMap grid;
  *grid.mutable_frame() = drawn.frame();
  grid.set_cells(drawn.cells());
  return CleanGridMap(grid, options);
}

AreaStages RunAreaStages(const proto::CleanedMap& map, const proto::PipelineOptions& options) {
  AreaStages stages;
  stages.options = options;
  stages.diagram = ComputeVoronoiStage(map, options.voronoi());
  stages.topology = BuildTopologyGraph(stages.diagram, map, options.prune());
  stages.cut = BuildCutGraph(stages.topology, map, options.cut());
  stages.areas = BuildAreaGraph(stages.cut, map, options.merge(), &stages.raster);
  return stages;
}

void ExpectAreaGraphInvariants(const AreaStages& stages, const proto::CleanedMap& map,
                               double min_coverage) {
  const proto::AreaGraph& graph = stages.areas;
  const AreaRaster& raster = stages.raster;
  const int area_count = graph.areas_size();
  ASSERT_GT(area_count, 0);
  ASSERT_EQ(static_cast<int>(raster.cell_count.size()), area_count);
  const cv::Size size(map.frame().width_px(), map.frame().height_px());

  // Simple polygons with positive area.
  for (const proto::Area& area : graph.areas()) {
    SCOPED_TRACE("area " + std::to_string(area.id()));
    EXPECT_TRUE(CgalSimple(area.polygon_px().outer()));
    for (const proto::Ring& hole : area.polygon_px().holes()) EXPECT_TRUE(CgalSimple(hole));
    std::vector<PointList> rings{ToPointList(area.polygon_px().outer().points())};
    for (const proto::Ring& hole : area.polygon_px().holes()) {
      rings.push_back(ToPointList(hole.points()));
    }
    EXPECT_TRUE(RingsAreSimple(rings));
    EXPECT_GT(SignedArea(rings[0]), 0);
    EXPECT_GT(area.area_m2(), 0);
    EXPECT_EQ(area.polygon_px().outer().points_size(), area.polygon_m().outer().points_size());
  }

  // Which polygons hold each cell centre; the raster labels agree.
  cv::Mat owners = cv::Mat::zeros(size, CV_32S);
  cv::Mat owner = cv::Mat::zeros(size, CV_32S);
  for (const proto::Area& area : graph.areas()) {
    const cv::Rect box = Bounds(area.polygon_px().outer(), size);
    for (int r = box.y; r < box.br().y; ++r) {
      for (int c = box.x; c < box.br().x; ++c) {
        if (!Inside(area.polygon_px(), c + 0.5, r + 0.5)) continue;
        ++owners.at<int>(r, c);
        owner.at<int>(r, c) = area.id() + 1;
      }
    }
  }
  // Simplification moves an outline by at most merge.outline_tolerance_m, so
  // a cell that the polygon of another area than its raster area holds lies
  // that close to a cell of that area.
  const double resolution_m = map.frame().resolution_m();
  const int reach =
      static_cast<int>(std::ceil(stages.options.merge().outline_tolerance_m() / resolution_m)) + 1;
  auto near_label = [&](int r, int c, int label) {
    for (int y = std::max(0, r - reach); y <= std::min(size.height - 1, r + reach); ++y) {
      for (int x = std::max(0, c - reach); x <= std::min(size.width - 1, c + reach); ++x) {
        if (raster.labels.at<int>(y, x) == label) return true;
      }
    }
    return false;
  };
  int64_t shared_cells = 0, polygon_cells = 0, far_disagreeing = 0;
  for (int r = 0; r < size.height; ++r) {
    for (int c = 0; c < size.width; ++c) {
      shared_cells += owners.at<int>(r, c) > 1;
      polygon_cells += owners.at<int>(r, c) > 0;
      const int label = raster.labels.at<int>(r, c), polygon = owner.at<int>(r, c);
      far_disagreeing += label > 0 && polygon > 0 && polygon != label && !near_label(r, c, polygon);
    }
  }
  EXPECT_EQ(shared_cells, 0) << "cells inside two area polygons";
  EXPECT_EQ(far_disagreeing, 0) << "cells held by another area's polygon beyond the tolerance";
  // The polygons tile: no two interiors overlap (exact), and every passage
  // is a piece of the border its two areas share.
  EXPECT_TRUE(OverlappingAreaPairs(graph).empty()) << "overlapping area polygons";
  for (const proto::Passage& passage : graph.passages()) {
    EXPECT_TRUE(PassageEndsOnBothOutlines(graph, passage)) << "passage " << passage.id();
    EXPECT_GE(passage.border_m_size(), 2) << "passage " << passage.id();
  }

  // Coverage of the free cells inside the boundary.
  int64_t covered = 0;
  for (int64_t n : raster.cell_count) covered += n;
  ASSERT_GT(raster.domain_cells, 0);
  EXPECT_GE(static_cast<double>(covered) / raster.domain_cells, min_coverage);
  EXPECT_GE(static_cast<double>(polygon_cells) / raster.domain_cells, min_coverage);
  const double min_gap_px =
      RunsStagePass(stages.options.merge(), proto::MergeOptions::GROWTH_STOPS_AT_NARROW_GAPS)
          ? map.robot_width_m() / map.frame().resolution_m()
          : 0;
  EXPECT_GE(static_cast<double>(covered) / ReachableCells(raster, map, stages.cut, min_gap_px),
            0.99);

  // Passages join two areas that meet there.
  const MapTransform transform(map.frame());
  std::vector<std::vector<int>> neighbours(area_count);
  for (const proto::Passage& passage : graph.passages()) {
    SCOPED_TRACE("passage " + std::to_string(passage.id()));
    ASSERT_GE(passage.area_a(), 0);
    ASSERT_GE(passage.area_b(), 0);
    ASSERT_LT(passage.area_a(), area_count);
    ASSERT_LT(passage.area_b(), area_count);
    EXPECT_NE(passage.area_a(), passage.area_b());
    EXPECT_GT(passage.width_m(), 0);
    neighbours[passage.area_a()].push_back(passage.area_b());
    neighbours[passage.area_b()].push_back(passage.area_a());
    const Eigen::Vector2d point =
        transform.WorldToPixel({passage.point_m().x(), passage.point_m().y()});
    const double reach = std::max(3.0, 0.5 * passage.width_m() / map.frame().resolution_m() + 2);
    bool seen_a = false, seen_b = false;
    for (int r = static_cast<int>(point.y() - reach); r <= point.y() + reach; ++r) {
      for (int c = static_cast<int>(point.x() - reach); c <= point.x() + reach; ++c) {
        if (c < 0 || r < 0 || c >= size.width || r >= size.height) continue;
        const int label = raster.labels.at<int>(r, c) - 1;
        seen_a = seen_a || label == passage.area_a();
        seen_b = seen_b || label == passage.area_b();
      }
    }
    EXPECT_TRUE(seen_a && seen_b) << "the two areas do not meet at the passage";
    for (int id : {passage.area_a(), passage.area_b()}) {
      const auto& ids = graph.areas(id).passage_ids();
      EXPECT_NE(std::find(ids.begin(), ids.end(), passage.id()), ids.end());
    }
  }

  // Connected through the passages into as many components as it says (one
  // per part of the map that prune kept).
  std::vector<bool> reached(area_count, false);
  int components = 0;
  for (int start = 0; start < area_count; ++start) {
    if (reached[start]) continue;
    ++components;
    std::deque<int> queue{start};
    reached[start] = true;
    while (!queue.empty()) {
      const int a = queue.front();
      queue.pop_front();
      for (int b : neighbours[a]) {
        if (!reached[b]) reached[b] = true, queue.push_back(b);
      }
    }
  }
  EXPECT_EQ(components, graph.components());
  EXPECT_LE(components, std::max(1, stages.cut.parts())) << "more components than parts of the map";

  // Every cut edge in exactly one area.
  std::multiset<int> edges;
  for (const proto::Area& area : graph.areas()) {
    EXPECT_GT(area.topology_edge_ids_size(), 0);
    edges.insert(area.topology_edge_ids().begin(), area.topology_edge_ids().end());
  }
  for (const proto::GraphEdge& edge : stages.cut.edges()) EXPECT_EQ(edges.count(edge.id()), 1u);
}

floorplan::FloorPlan TwoRoomsWithADoor() {
  floorplan::FloorPlan plan(9.5, 5);
  floorplan::DrawRoom(plan, {0.5, 0.5, 4, 4});
  floorplan::DrawRoom(plan, {4.5, 0.5, 4.5, 4});
  floorplan::DrawDoor(plan, 4.5, 2.5, 0.9, floorplan::WallDirection::kVertical);
  return plan;
}

floorplan::FloorPlan LCorridor() {
  floorplan::FloorPlan plan(7.5, 7.5);
  floorplan::DrawRegion(plan, {{0.5, 0.5, 1.15, 6.5}, {0.5, 5.85, 6.5, 1.15}});
  return plan;
}

floorplan::FloorPlan FiveByFiveMaze() {
  floorplan::FloorPlan plan(6.75, 6.75);
  floorplan::DrawMaze(plan, {0.5, 0.5, 5.75, 5.75}, 5, 5, 7);
  return plan;
}

proto::PipelineOptions PaperMazeOptions() {
  proto::PipelineOptions options;
  options.mutable_cut()->set_room_width_m(2.0);
  // Every area kept (the default folds areas below merge.min_area_m2, and the
  // dead ends hold about 1-3 m2), and no corridor pieces joined (neither two
  // uniform pieces nor pieces the room disk split: a maze's passages are as
  // wide as its cells' openings and run straight on).
  options.mutable_merge()->set_min_area_m2(0);
  options.mutable_merge()->add_skip_passes(proto::MergeOptions::JOIN_CORRIDOR_PIECES);
  options.mutable_merge()->add_skip_passes(proto::MergeOptions::JOIN_SPLIT_CORRIDORS);
  return options;
}

int AreaAt(const proto::AreaGraph& graph, double x_m, double y_m, double resolution_m) {
  for (const proto::Area& area : graph.areas()) {
    if (Inside(area.polygon_px(), x_m / resolution_m, y_m / resolution_m)) return area.id();
  }
  return -1;
}

}  // namespace areagraph::testing

#include "stages/merge/area_graph_geometry.h"

#include <algorithm>

#include "stages/common/map_frame.h"
#include "stages/common/skipped_passes.h"
#include "stages/merge/area_outlines.h"
#include "stages/merge/open_borders.h"
#include "stages/merge/passage_borders.h"
#include "stages/merge/passage_finder.h"
#include "stages/merge/planar_partition.h"

namespace areagraph {
namespace {

void SetRing(const PointList& points, const MapTransform& transform, proto::Ring* px,
             proto::Ring* m) {
  for (const Eigen::Vector2d& p : points) {
    *px->add_points() = ToProtoPoint(p);
    *m->add_points() = ToProtoPoint(transform.PixelToWorld(p));
  }
}

// Area (square pixels) and centroid of a polygon with holes.
std::pair<double, Eigen::Vector2d> AreaAndCentroid(const AreaOutline& outline) {
  double twice_area = 0;
  Eigen::Vector2d moment = Eigen::Vector2d::Zero();
  auto add_ring = [&](const PointList& ring) {
    for (size_t i = 0; i < ring.size(); ++i) {
      const Eigen::Vector2d& a = ring[i];
      const Eigen::Vector2d& b = ring[(i + 1) % ring.size()];
      const double cross = a.x() * b.y() - b.x() * a.y();
      twice_area += cross;
      moment += cross * (a + b);
    }
  };
  add_ring(outline.outer);
  for (const PointList& hole : outline.holes) add_ring(hole);
  return {0.5 * twice_area, moment / (3 * twice_area)};
}

}  // namespace

void AddAreasAndPassages(const proto::CutGraph& graph, const AreaPlan& plan,
                         const AreaRaster& raster, const proto::MergeOptions& options,
                         proto::AreaGraph* out, const std::function<void()>& labels_done) {
  const int area_count = static_cast<int>(plan.areas.size());
  const MapTransform transform(out->frame());
  const double resolution_m = transform.resolution_m();
  const PlanarPartition partition = BuildPlanarPartition(raster.labels, area_count);
  // Read before the simplification lets the labels go.
  const double clearance_m = RunsStagePass(options, proto::MergeOptions::OPEN_BORDER_PASSAGES)
                                 ? graph.min_clearance_m()
                                 : 0;
  const std::vector<bool> passable =
      PassableChains(partition, raster.labels, clearance_m / resolution_m);
  const PartitionOutlines outlines =
      SimplifiedOutlines(partition, raster.labels, options.outline_tolerance_m() / resolution_m,
                         options.min_hole_m2() / (resolution_m * resolution_m), labels_done);

  std::vector<int> area_id(area_count, -1);
  std::vector<int> label_of_area;
  for (int k = 0; k < area_count; ++k) {
    const AreaOutline& outline = outlines.areas[k];
    if (raster.cell_count[k] == 0 || outline.outer.size() < 3) continue;
    area_id[k] = out->areas_size();
    label_of_area.push_back(k + 1);
    proto::Area* area = out->add_areas();
    area->set_id(area_id[k]);
    SetRing(outline.outer, transform, area->mutable_polygon_px()->mutable_outer(),
            area->mutable_polygon_m()->mutable_outer());
    for (const PointList& hole : outline.holes) {
      SetRing(hole, transform, area->mutable_polygon_px()->add_holes(),
              area->mutable_polygon_m()->add_holes());
    }
    const auto [area_px2, centroid_px] = AreaAndCentroid(outline);
    area->set_area_m2(area_px2 * resolution_m * resolution_m);
    *area->mutable_centroid_m() = ToProtoPoint(transform.PixelToWorld(centroid_px));
    area->set_kind(plan.areas[k].kind);
    for (int e : plan.areas[k].edges) area->add_topology_edge_ids(graph.edges(e).id());
  }

  std::vector<int> final_area_of_edge(graph.edges_size(), -1);
  for (int e = 0; e < graph.edges_size(); ++e) {
    final_area_of_edge[e] = area_id[plan.area_of_edge[e]];
  }
  std::vector<PassageOnBorder> placed =
      PlacePassagesOnBorders(FindPassages(graph, final_area_of_edge), partition, label_of_area);
  const std::vector<PassageOnBorder> open =
      OpenBorderPassages(partition, passable, outlines.chains, label_of_area, placed);
  placed.insert(placed.end(), open.begin(), open.end());
  for (const PassageOnBorder& on_border : placed) {
    const PassagePlan& plan_passage = on_border.passage;
    proto::Passage* passage = out->add_passages();
    passage->set_id(out->passages_size() - 1);
    passage->set_area_a(plan_passage.area_a);
    passage->set_area_b(plan_passage.area_b);
    *passage->mutable_point_m() = ToProtoPoint(transform.PixelToWorld(plan_passage.point));
    passage->set_width_m(plan_passage.width_px * resolution_m);
    PointList border;
    if (on_border.chain >= 0) {
      border = outlines.chains[on_border.chain];
      // area_a on the right on screen, so on the left in world metres.
      if (partition.chains[on_border.chain].right != label_of_area[plan_passage.area_a]) {
        std::reverse(border.begin(), border.end());
      }
    }
    const Eigen::Vector2d a = border.empty() ? plan_passage.side_a : border.front();
    const Eigen::Vector2d b = border.empty() ? plan_passage.side_b : border.back();
    *passage->mutable_segment_m()->mutable_a() = ToProtoPoint(transform.PixelToWorld(a));
    *passage->mutable_segment_m()->mutable_b() = ToProtoPoint(transform.PixelToWorld(b));
    for (const Eigen::Vector2d& p : border) {
      *passage->add_border_m() = ToProtoPoint(transform.PixelToWorld(p));
    }
    out->mutable_areas(plan_passage.area_a)->add_passage_ids(passage->id());
    out->mutable_areas(plan_passage.area_b)->add_passage_ids(passage->id());
  }
}

}  // namespace areagraph

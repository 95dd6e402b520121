// The viewer's Area Graph layer and the room width W behind it.
#include <Eigen/Core>
#include <cmath>
#include <cstdio>

#include "stages/common/map_frame.h"
#include "tools/export/area_polygons.h"
#include "tools/export/svg_path.h"
#include "tools/export/viewer_layers.h"

namespace areagraph {
namespace {

// Sets `out` to the pixel position of a point in map metres, rounded for the page.
void SetPixel(const MapTransform& transform, const proto::Point2& metres, viewer::Point* out) {
  const Eigen::Vector2d pixel = transform.WorldToPixel({metres.x(), metres.y()});
  out->set_x(Rounded(pixel.x(), 1));
  out->set_y(Rounded(pixel.y(), 1));
}

// "1.35 m": widths in the rule's words.
std::string Metres(double value) {
  char text[32];
  std::snprintf(text, sizeof(text), "%.2f m", value);
  return text;
}

bool Near(double a, double b) { return std::abs(a - b) < 1e-6; }

// Which of EstimateRoomWidth's (or RoomWidthM's) cases gave W, in words.
std::string RuleOf(const proto::RoomWidthEstimate& estimate, const proto::CutOptions& options) {
  const double w = estimate.room_width_m();
  if (!estimate.automatic()) {
    if (options.door_width_m() > 0 && options.corridor_width_m() > 0) {
      return "fixed: the paper's rule on cut.door_width_m and cut.corridor_width_m";
    }
    return "fixed: cut.room_width_m";
  }
  const double door = estimate.widest_door_m(), corridor = estimate.narrowest_corridor_m();
  if (door > 0 && Near(w, door + 0.1)) return "estimated: widest door " + Metres(door) + " + 0.1 m";
  if (corridor > 0 && Near(w, corridor - 0.1)) {
    return "estimated: narrowest corridor " + Metres(corridor) + " - 0.1 m";
  }
  // Neither case: held at the least W (clean.robot_width_m + 0.1 m).
  if (door > 0 || corridor > 0) return "estimated, held at the minimum " + Metres(w);
  return "no door or corridor found: the fallback cut.room_width_m";
}

}  // namespace

viewer::RoomWidth RoomWidthOf(const proto::RoomWidthEstimate& estimate,
                              const proto::CutOptions& options) {
  viewer::RoomWidth width;
  width.set_room_width_m(Rounded(estimate.room_width_m(), 3));
  width.set_automatic(estimate.automatic());
  width.set_widest_door_m(Rounded(estimate.widest_door_m(), 3));
  width.set_narrowest_corridor_m(Rounded(estimate.narrowest_corridor_m(), 3));
  width.set_rule(RuleOf(estimate, options));
  for (const proto::DetectedWidth& door : estimate.doors()) {
    viewer::DetectedWidth* added = width.add_doors();
    added->set_x(Rounded(door.position().x(), 1));
    added->set_y(Rounded(door.position().y(), 1));
    added->set_width_m(Rounded(door.width_m(), 3));
    // Doors wider than the one taken as the widest were left out as strays.
    added->set_counted(door.width_m() <= estimate.widest_door_m() + 1e-9);
  }
  for (const proto::DetectedWidth& corridor : estimate.corridors()) {
    viewer::DetectedWidth* added = width.add_corridors();
    added->set_x(Rounded(corridor.position().x(), 1));
    added->set_y(Rounded(corridor.position().y(), 1));
    added->set_width_m(Rounded(corridor.width_m(), 3));
    added->set_length_m(Rounded(corridor.length_m(), 2));
  }
  return width;
}

viewer::AreaLayer AreaLayerOf(const proto::AreaGraph& graph) {
  const MapTransform transform(graph.frame());
  viewer::AreaLayer layer;
  for (const proto::Area& area : graph.areas()) {
    viewer::Area* added = layer.add_areas();
    added->set_id(area.id());
    added->set_kind(AreaKindName(area.kind()));
    added->set_area_m2(Rounded(area.area_m2(), 2));
    added->set_path(PolygonPath(AreaPolygonPixels(graph, area)));
    SetPixel(transform, area.centroid_m(), added->mutable_label_at());
    added->mutable_topology_edge_ids()->CopyFrom(area.topology_edge_ids());
    added->mutable_passage_ids()->CopyFrom(area.passage_ids());
    if (graph.has_version()) added->set_stable_id(area.stable_id());
  }
  for (const proto::Passage& passage : graph.passages()) {
    viewer::Passage* added = layer.add_passages();
    added->set_id(passage.id());
    added->set_area_a(passage.area_a());
    added->set_area_b(passage.area_b());
    added->set_width_m(Rounded(passage.width_m(), 3));
    SetPixel(transform, passage.segment_m().a(), added->mutable_a());
    SetPixel(transform, passage.segment_m().b(), added->mutable_b());
    SetPixel(transform, passage.point_m(), added->mutable_at());
    if (graph.has_version()) added->set_stable_id(passage.stable_id());
  }
  return layer;
}

}  // namespace areagraph

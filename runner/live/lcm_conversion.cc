// Area Graph <-> area_graph_t, and decoding of raw LCM bytes. The grid map
// conversions are in grid_map_conversion.cc.
#include "runner/live/lcm_conversion.h"

#include <cmath>
#include <set>
#include <sstream>

#include "common/error.h"
#include "runner/live/lcm_message_bounds.h"
#include "stages/common/map_frame.h"
#include "stages/common/stage_info.h"

namespace areagraph {
namespace {

areagraph_lcm::ring_t ToLcmRing(const proto::Ring& ring) {
  areagraph_lcm::ring_t out;
  out.num_points = ring.points_size();
  for (const proto::Point2& point : ring.points()) {
    out.x.push_back(point.x());
    out.y.push_back(point.y());
  }
  return out;
}

int8_t ToLcmKind(proto::AreaKind kind) {
  switch (kind) {
    case proto::AREA_CORRIDOR:
      return areagraph_lcm::area_t::CORRIDOR;
    case proto::AREA_DEAD_END:
      return areagraph_lcm::area_t::DEAD_END;
    default:
      return areagraph_lcm::area_t::ROOM;
  }
}

// Throws InputError "area_graph_t for map 'x': <what>".
[[noreturn]] void Reject(const std::string& map_name, const std::string& what) {
  throw InputError("area_graph_t for map '" + map_name + "': " + what);
}

void CheckFinite(const std::string& map_name, double value, const std::string& what) {
  if (!std::isfinite(value)) Reject(map_name, what + " is not finite");
}

// The ring in metres and in pixels; rings need three points to enclose area.
void FromLcmRing(const std::string& map_name, const areagraph_lcm::ring_t& ring,
                 const MapTransform& transform, const std::string& what, proto::Ring* metres,
                 proto::Ring* pixels) {
  if (ring.num_points < 3) Reject(map_name, what + " has fewer than 3 points");
  for (int i = 0; i < ring.num_points; ++i) {
    CheckFinite(map_name, ring.x[i], what + " x");
    CheckFinite(map_name, ring.y[i], what + " y");
    proto::Point2* metre_point = metres->add_points();
    metre_point->set_x(ring.x[i]);
    metre_point->set_y(ring.y[i]);
    const Eigen::Vector2d pixel = transform.WorldToPixel({ring.x[i], ring.y[i]});
    proto::Point2* pixel_point = pixels->add_points();
    pixel_point->set_x(pixel.x());
    pixel_point->set_y(pixel.y());
  }
}

proto::Point2 Point(double x, double y) {
  proto::Point2 point;
  point.set_x(x);
  point.set_y(y);
  return point;
}

}  // namespace

areagraph_lcm::area_graph_t ToLcmAreaGraph(const std::string& map_name,
                                           const std::string& cache_key,
                                           const proto::AreaGraph& graph) {
  areagraph_lcm::area_graph_t out;
  out.map_name = map_name;
  out.artifact_key = cache_key;
  const proto::MapFrame& frame = graph.frame();
  out.resolution_m = frame.resolution_m();
  out.origin_x_m = frame.origin_x_m();
  out.origin_y_m = frame.origin_y_m();
  out.origin_yaw_rad = frame.origin_yaw_rad();
  out.width_px = frame.width_px();
  out.height_px = frame.height_px();
  for (const proto::Area& area : graph.areas()) {
    areagraph_lcm::area_t lcm_area;
    lcm_area.id = area.id();
    lcm_area.kind = ToLcmKind(area.kind());
    lcm_area.outer = ToLcmRing(area.polygon_m().outer());
    for (const proto::Ring& hole : area.polygon_m().holes()) {
      lcm_area.holes.push_back(ToLcmRing(hole));
    }
    lcm_area.num_holes = static_cast<int32_t>(lcm_area.holes.size());
    lcm_area.area_m2 = area.area_m2();
    lcm_area.centroid_x = area.centroid_m().x();
    lcm_area.centroid_y = area.centroid_m().y();
    lcm_area.passage_ids.assign(area.passage_ids().begin(), area.passage_ids().end());
    lcm_area.num_passages = static_cast<int32_t>(lcm_area.passage_ids.size());
    out.areas.push_back(std::move(lcm_area));
  }
  out.num_areas = static_cast<int32_t>(out.areas.size());
  for (const proto::Passage& passage : graph.passages()) {
    areagraph_lcm::passage_t lcm_passage;
    lcm_passage.id = passage.id();
    lcm_passage.area_a = passage.area_a();
    lcm_passage.area_b = passage.area_b();
    lcm_passage.x = passage.point_m().x();
    lcm_passage.y = passage.point_m().y();
    lcm_passage.ax = passage.segment_m().a().x();
    lcm_passage.ay = passage.segment_m().a().y();
    lcm_passage.bx = passage.segment_m().b().x();
    lcm_passage.by = passage.segment_m().b().y();
    lcm_passage.width_m = passage.width_m();
    for (const proto::Point2& point : passage.border_m()) {
      lcm_passage.border_x.push_back(point.x());
      lcm_passage.border_y.push_back(point.y());
    }
    lcm_passage.num_border_points = static_cast<int32_t>(lcm_passage.border_x.size());
    out.passages.push_back(lcm_passage);
  }
  out.num_passages = static_cast<int32_t>(out.passages.size());
  return out;
}

proto::AreaGraph AreaGraphFromLcm(const areagraph_lcm::area_graph_t& message) {
  const std::string& name = message.map_name;
  CheckLcmMapName(name);
  if (!(message.resolution_m > 0) || !std::isfinite(message.resolution_m)) {
    Reject(name, "resolution_m must be positive and finite");
  }
  CheckFinite(name, message.origin_x_m, "origin_x_m");
  CheckFinite(name, message.origin_y_m, "origin_y_m");
  CheckFinite(name, message.origin_yaw_rad, "origin_yaw_rad");
  if (message.width_px <= 0 || message.height_px <= 0)
    Reject(name, "the grid size is not positive");

  proto::AreaGraph graph;
  graph.set_format_version(kAreaGraphFormatVersion);
  proto::MapFrame* frame = graph.mutable_frame();
  frame->set_resolution_m(message.resolution_m);
  frame->set_origin_x_m(message.origin_x_m);
  frame->set_origin_y_m(message.origin_y_m);
  frame->set_origin_yaw_rad(message.origin_yaw_rad);
  frame->set_width_px(message.width_px);
  frame->set_height_px(message.height_px);
  const MapTransform transform(*frame);

  std::set<int32_t> area_ids;
  for (const areagraph_lcm::area_t& lcm_area : message.areas) {
    const std::string what = "area " + std::to_string(lcm_area.id);
    if (!area_ids.insert(lcm_area.id).second)
      Reject(name, "two areas have id " + std::to_string(lcm_area.id));
    if (lcm_area.kind < areagraph_lcm::area_t::ROOM ||
        lcm_area.kind > areagraph_lcm::area_t::DEAD_END) {
      Reject(name, what + " has unknown kind " + std::to_string(lcm_area.kind));
    }
    proto::Area* area = graph.add_areas();
    area->set_id(lcm_area.id);
    area->set_kind(static_cast<proto::AreaKind>(lcm_area.kind));
    FromLcmRing(name, lcm_area.outer, transform, what + " outline",
                area->mutable_polygon_m()->mutable_outer(),
                area->mutable_polygon_px()->mutable_outer());
    for (const areagraph_lcm::ring_t& hole : lcm_area.holes) {
      FromLcmRing(name, hole, transform, what + " hole", area->mutable_polygon_m()->add_holes(),
                  area->mutable_polygon_px()->add_holes());
    }
    CheckFinite(name, lcm_area.area_m2, what + " area_m2");
    CheckFinite(name, lcm_area.centroid_x, what + " centroid_x");
    CheckFinite(name, lcm_area.centroid_y, what + " centroid_y");
    area->set_area_m2(lcm_area.area_m2);
    *area->mutable_centroid_m() = Point(lcm_area.centroid_x, lcm_area.centroid_y);
    for (int32_t id : lcm_area.passage_ids) area->add_passage_ids(id);
  }

  std::set<int32_t> passage_ids;
  for (const areagraph_lcm::passage_t& lcm_passage : message.passages) {
    const std::string what = "passage " + std::to_string(lcm_passage.id);
    if (!passage_ids.insert(lcm_passage.id).second)
      Reject(name, "two passages have id " + std::to_string(lcm_passage.id));
    if (area_ids.count(lcm_passage.area_a) == 0 || area_ids.count(lcm_passage.area_b) == 0) {
      Reject(name, what + " joins an area that is not in the graph");
    }
    for (double value : {lcm_passage.x, lcm_passage.y, lcm_passage.ax, lcm_passage.ay,
                         lcm_passage.bx, lcm_passage.by, lcm_passage.width_m}) {
      CheckFinite(name, value, what + " geometry");
    }
    proto::Passage* passage = graph.add_passages();
    passage->set_id(lcm_passage.id);
    passage->set_area_a(lcm_passage.area_a);
    passage->set_area_b(lcm_passage.area_b);
    *passage->mutable_point_m() = Point(lcm_passage.x, lcm_passage.y);
    *passage->mutable_segment_m()->mutable_a() = Point(lcm_passage.ax, lcm_passage.ay);
    *passage->mutable_segment_m()->mutable_b() = Point(lcm_passage.bx, lcm_passage.by);
    passage->set_width_m(lcm_passage.width_m);
    for (int i = 0; i < lcm_passage.num_border_points; ++i) {
      CheckFinite(name, lcm_passage.border_x[i], what + " border x");
      CheckFinite(name, lcm_passage.border_y[i], what + " border y");
      *passage->add_border_m() = Point(lcm_passage.border_x[i], lcm_passage.border_y[i]);
    }
  }
  for (const proto::Area& area : graph.areas()) {
    for (int32_t id : area.passage_ids()) {
      if (passage_ids.count(id) == 0) {
        Reject(name, "area " + std::to_string(area.id()) + " lists passage " + std::to_string(id) +
                         ", which is not in the graph");
      }
    }
  }
  return graph;
}

void CheckLcmMapName(const std::string& name) {
  if (name.empty() || name.size() > 256) {
    throw InputError("map name must have 1 to 256 characters, got " + std::to_string(name.size()));
  }
  // '/' is allowed: ag-run names the maps of a directory by their relative path.
  for (char c : name) {
    const bool allowed = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') ||
                         (c >= '0' && c <= '9') || c == '_' || c == '-' || c == '.' || c == '/';
    if (!allowed) {
      throw InputError("map name may only hold letters, digits, '_', '-', '.' and '/'");
    }
  }
  if (name.front() == '/' || ("/" + name + "/").find("/../") != std::string::npos) {
    throw InputError("map name '" + name + "' must not start with '/' or contain '..'");
  }
}

namespace {

// Decodes `Message` after `encoded_size` vouched for its counts.
template <typename Message>
Message DecodeChecked(const void* data, int size, int (*encoded_size)(const void*, int)) {
  const std::string type = Message::getTypeName();
  if (data == nullptr || size < 8) {
    throw InputError("not a message of type " + type + ": only " + std::to_string(size) + " bytes");
  }
  // The fingerprint comes first so that a message of another type says so.
  int64_t fingerprint = 0;
  __int64_t_decode_array(data, 0, size, &fingerprint, 1);
  if (fingerprint != Message::getHash()) {
    throw InputError("not a message of type " + type + " (type fingerprint does not match)");
  }
  const int expected = encoded_size(data, size);
  if (expected < 0) {
    throw InputError("malformed " + type + ": truncated or with impossible array sizes");
  }
  if (expected != size) {
    throw InputError("malformed " + type + ": " + std::to_string(size - expected) +
                     " bytes after the message");
  }
  Message message;
  if (message.decode(data, 0, size) != size) throw InputError("malformed " + type);
  return message;
}

}  // namespace

areagraph_lcm::grid_map_t DecodeGridMapMessage(const void* data, int size) {
  return DecodeChecked<areagraph_lcm::grid_map_t>(data, size, GridMapEncodedSize);
}

areagraph_lcm::area_graph_t DecodeAreaGraphMessage(const void* data, int size) {
  return DecodeChecked<areagraph_lcm::area_graph_t>(data, size, AreaGraphEncodedSize);
}

}  // namespace areagraph

// Area Graph <-> area_graph_t, and decoding of raw LCM bytes. The grid map
// conversions are in grid_map_conversion.cc.
#include "runner/live/lcm_conversion.h"

#include <cmath>
#include <map>
#include <set>
#include <sstream>

#include "common/error.h"
#include "common/map_name.h"
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

// The ids a graph goes out with: its stable ids when it has them (a match
// artifact), else its own (a graph made before stable ids existed).
class LcmIds {
 public:
  explicit LcmIds(const proto::AreaGraph& graph) : stable_(graph.has_version()) {
    for (const proto::Area& area : graph.areas()) {
      area_ids_[area.id()] = stable_ ? area.stable_id() : area.id();
    }
    for (const proto::Passage& passage : graph.passages()) {
      passage_ids_[passage.id()] = stable_ ? passage.stable_id() : passage.id();
    }
  }
  int32_t area(int32_t id) const { return Find(area_ids_, id, "area"); }
  int32_t passage_by_id(int32_t id) const { return Find(passage_ids_, id, "passage"); }
  int32_t passage(const proto::Passage& passage) const { return passage_by_id(passage.id()); }

 private:
  static int32_t Find(const std::map<int32_t, int32_t>& ids, int32_t id, const char* what) {
    const auto found = ids.find(id);
    if (found == ids.end()) {
      throw InputError(std::string("the Area Graph refers to ") + what + " " + std::to_string(id) +
                       ", which it does not have");
    }
    return found->second;
  }

  bool stable_;
  std::map<int32_t, int32_t> area_ids_;
  std::map<int32_t, int32_t> passage_ids_;
};

areagraph_lcm::area_t ToLcmArea(const proto::Area& area, const LcmIds& ids) {
  areagraph_lcm::area_t lcm_area;
  lcm_area.id = ids.area(area.id());
  lcm_area.kind = ToLcmKind(area.kind());
  lcm_area.outer = ToLcmRing(area.polygon_m().outer());
  for (const proto::Ring& hole : area.polygon_m().holes()) {
    lcm_area.holes.push_back(ToLcmRing(hole));
  }
  lcm_area.num_holes = static_cast<int32_t>(lcm_area.holes.size());
  lcm_area.area_m2 = area.area_m2();
  lcm_area.centroid_x = area.centroid_m().x();
  lcm_area.centroid_y = area.centroid_m().y();
  for (int32_t id : area.passage_ids()) lcm_area.passage_ids.push_back(ids.passage_by_id(id));
  lcm_area.num_passages = static_cast<int32_t>(lcm_area.passage_ids.size());
  return lcm_area;
}

areagraph_lcm::passage_t ToLcmPassage(const proto::Passage& passage, const LcmIds& ids) {
  areagraph_lcm::passage_t lcm_passage;
  lcm_passage.id = ids.passage(passage);
  lcm_passage.area_a = ids.area(passage.area_a());
  lcm_passage.area_b = ids.area(passage.area_b());
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
  return lcm_passage;
}

}  // namespace

areagraph_lcm::area_graph_t ToLcmAreaGraph(const std::string& map_name,
                                           const std::string& cache_key,
                                           const proto::AreaGraph& graph) {
  areagraph_lcm::area_graph_t out;
  out.map_name = map_name;
  out.artifact_key = cache_key;
  out.version = graph.version().number();
  out.predecessor_key = graph.version().predecessor_key();
  out.utime = 0;
  out.sequence = 0;
  out.map_utime = 0;
  const proto::MapFrame& frame = graph.frame();
  out.resolution_m = frame.resolution_m();
  out.origin_x_m = frame.origin_x_m();
  out.origin_y_m = frame.origin_y_m();
  out.origin_yaw_rad = frame.origin_yaw_rad();
  out.width_px = frame.width_px();
  out.height_px = frame.height_px();
  const LcmIds ids(graph);
  for (const proto::Area& area : graph.areas()) out.areas.push_back(ToLcmArea(area, ids));
  out.num_areas = static_cast<int32_t>(out.areas.size());
  for (const proto::Passage& passage : graph.passages()) {
    out.passages.push_back(ToLcmPassage(passage, ids));
  }
  out.num_passages = static_cast<int32_t>(out.passages.size());
  return out;
}

areagraph_lcm::area_graph_diff_t ToLcmAreaGraphDiff(const std::string& map_name,
                                                    const std::string& cache_key,
                                                    const proto::AreaGraphDiff& diff,
                                                    const proto::AreaGraph& after) {
  areagraph_lcm::area_graph_diff_t out;
  out.map_name = map_name;
  out.artifact_key = cache_key;
  out.version = diff.to_version();
  out.predecessor_key = after.version().predecessor_key();
  out.predecessor_version = diff.from_version();
  out.utime = 0;
  out.sequence = 0;
  out.map_utime = 0;
  const LcmIds ids(after);
  std::map<int32_t, const proto::Area*> areas;
  for (const proto::Area& area : after.areas()) areas[ids.area(area.id())] = &area;
  std::map<int32_t, const proto::Passage*> passages;
  for (const proto::Passage& passage : after.passages()) passages[ids.passage(passage)] = &passage;
  for (int32_t id : diff.added_areas()) out.added_areas.push_back(ToLcmArea(*areas.at(id), ids));
  out.removed_area_ids.assign(diff.removed_areas().begin(), diff.removed_areas().end());
  for (const proto::AreaChange& change : diff.changed_areas()) {
    areagraph_lcm::area_change_t lcm_change;
    lcm_change.changes = static_cast<int8_t>(
        (change.grown() ? areagraph_lcm::area_change_t::GROWN : 0) |
        (change.shrunk() ? areagraph_lcm::area_change_t::SHRUNK : 0) |
        (change.split_into_size() > 0 ? areagraph_lcm::area_change_t::SPLIT : 0) |
        (change.merged_from_size() > 0 ? areagraph_lcm::area_change_t::MERGED : 0) |
        (change.kind_changed() ? areagraph_lcm::area_change_t::KIND : 0) |
        (change.passages_changed() ? areagraph_lcm::area_change_t::PASSAGES : 0));
    lcm_change.area = ToLcmArea(*areas.at(change.stable_id()), ids);
    lcm_change.split_into.assign(change.split_into().begin(), change.split_into().end());
    lcm_change.num_split_into = static_cast<int32_t>(lcm_change.split_into.size());
    lcm_change.merged_from.assign(change.merged_from().begin(), change.merged_from().end());
    lcm_change.num_merged_from = static_cast<int32_t>(lcm_change.merged_from.size());
    out.changed_areas.push_back(std::move(lcm_change));
  }
  out.unchanged_areas = diff.unchanged_areas_size();
  for (int32_t id : diff.added_passages()) {
    out.added_passages.push_back(ToLcmPassage(*passages.at(id), ids));
  }
  out.removed_passage_ids.assign(diff.removed_passages().begin(), diff.removed_passages().end());
  for (const proto::PassageChange& change : diff.changed_passages()) {
    out.changed_passages.push_back(ToLcmPassage(*passages.at(change.stable_id()), ids));
  }
  out.unchanged_passages = diff.unchanged_passages_size();
  out.num_added_areas = static_cast<int32_t>(out.added_areas.size());
  out.num_removed_areas = static_cast<int32_t>(out.removed_area_ids.size());
  out.num_changed_areas = static_cast<int32_t>(out.changed_areas.size());
  out.num_added_passages = static_cast<int32_t>(out.added_passages.size());
  out.num_removed_passages = static_cast<int32_t>(out.removed_passage_ids.size());
  out.num_changed_passages = static_cast<int32_t>(out.changed_passages.size());
  return out;
}

proto::AreaGraph AreaGraphFromLcm(const areagraph_lcm::area_graph_t& message) {
  const std::string& name = message.map_name;
  CheckMapName(name);
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

  // The message's ids are stable ids; in the artifact, ids are indices (as
  // ag-merge makes them) and the message's ids become the stable ids.
  std::map<int32_t, int32_t> area_index, passage_index;
  for (const areagraph_lcm::passage_t& lcm_passage : message.passages) {
    if (!passage_index.emplace(lcm_passage.id, passage_index.size()).second) {
      Reject(name, "two passages have id " + std::to_string(lcm_passage.id));
    }
  }
  for (const areagraph_lcm::area_t& lcm_area : message.areas) {
    const std::string what = "area " + std::to_string(lcm_area.id);
    if (!area_index.emplace(lcm_area.id, area_index.size()).second)
      Reject(name, "two areas have id " + std::to_string(lcm_area.id));
    if (lcm_area.kind < areagraph_lcm::area_t::ROOM ||
        lcm_area.kind > areagraph_lcm::area_t::DEAD_END) {
      Reject(name, what + " has unknown kind " + std::to_string(lcm_area.kind));
    }
    proto::Area* area = graph.add_areas();
    area->set_id(graph.areas_size() - 1);
    area->set_stable_id(lcm_area.id);
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
    for (int32_t id : lcm_area.passage_ids) {
      const auto passage = passage_index.find(id);
      if (passage == passage_index.end()) {
        Reject(name, what + " lists passage " + std::to_string(id) + ", which is not in the graph");
      }
      area->add_passage_ids(passage->second);
    }
  }

  for (const areagraph_lcm::passage_t& lcm_passage : message.passages) {
    const std::string what = "passage " + std::to_string(lcm_passage.id);
    if (area_index.count(lcm_passage.area_a) == 0 || area_index.count(lcm_passage.area_b) == 0) {
      Reject(name, what + " joins an area that is not in the graph");
    }
    for (double value : {lcm_passage.x, lcm_passage.y, lcm_passage.ax, lcm_passage.ay,
                         lcm_passage.bx, lcm_passage.by, lcm_passage.width_m}) {
      CheckFinite(name, value, what + " geometry");
    }
    proto::Passage* passage = graph.add_passages();
    passage->set_id(graph.passages_size() - 1);
    passage->set_stable_id(lcm_passage.id);
    passage->set_area_a(area_index.at(lcm_passage.area_a));
    passage->set_area_b(area_index.at(lcm_passage.area_b));
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
  if (message.version < 0) Reject(name, "version " + std::to_string(message.version) + " < 0");
  if (message.version > 0) {
    proto::AreaGraphVersion* version = graph.mutable_version();
    version->set_number(message.version);
    version->set_predecessor_key(message.predecessor_key);
    // Ids above every one received: what the publisher gave out before is unknown.
    version->set_next_area_id(area_index.empty() ? 0 : area_index.rbegin()->first + 1);
    version->set_next_passage_id(passage_index.empty() ? 0 : passage_index.rbegin()->first + 1);
  }
  return graph;
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

areagraph_lcm::area_graph_diff_t DecodeAreaGraphDiffMessage(const void* data, int size) {
  return DecodeChecked<areagraph_lcm::area_graph_diff_t>(data, size, AreaGraphDiffEncodedSize);
}

}  // namespace areagraph

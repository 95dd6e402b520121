#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "tools/export/geo_anchor.h"

namespace areagraph {

// One OSM XML <tag/> line, key and value escaped.
std::string OsmTag(const std::string& key, const std::string& value);

// One OSM XML <way> over `nodes` with `tags` (OsmTag lines).
std::string OsmWayXml(int64_t id, const std::vector<int64_t>& nodes, const std::string& tags);

// Hands out negative ids (new objects for JOSM) and one <node> per distinct
// position to the micrometre, so that outlines through the same vertex share
// the node.
class OsmNodeTable {
 public:
  explicit OsmNodeTable(const GeoAnchor& anchor) : anchor_(anchor) {}

  int64_t NextId() { return next_id_--; }

  // The node at world metres (x, y), made on first use. Throws InputError
  // for coordinates that are not finite.
  int64_t NodeAt(double x_m, double y_m);

  // A node at the anchor itself with `tags`.
  void AddAnchorNode(const std::string& tags);

  // Every <node> made so far, in order.
  const std::string& xml() const { return xml_; }

 private:
  GeoAnchor anchor_;
  int64_t next_id_ = -1;
  std::map<std::pair<int64_t, int64_t>, int64_t> ids_;
  std::string xml_;
};

}  // namespace areagraph

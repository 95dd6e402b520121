#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "tools/export/geo_anchor.h"
#include "tools/export/snap_rounding.h"

namespace areagraph {

// `value` with `decimals` digits after the point, however long it gets (no
// fixed buffer: 1.7e308 has 309 digits before the point).
std::string FixedDecimals(double value, int decimals);

// One OSM XML <tag/> line, key and value escaped.
std::string OsmTag(const std::string& key, const std::string& value);

// One OSM XML <way> over `nodes` with `tags` (OsmTag lines).
std::string OsmWayXml(int64_t id, const std::vector<int64_t>& nodes, const std::string& tags);

// A member of a relation: a way and its role.
struct OsmWayMember {
  int64_t way = 0;
  std::string role;
};

// One OSM XML <relation> of `members` with `tags` (OsmTag lines).
std::string OsmRelationXml(int64_t id, const std::vector<OsmWayMember>& members,
                           const std::string& tags);

// Hands out negative ids (new objects for JOSM) and one <node> per distinct
// position at OSM's precision (7 decimals of a degree, about a centimetre),
// so that outlines through the same vertex share the node and no two nodes
// lie at one written position (which JOSM reports as duplicated nodes).
class OsmNodeTable {
 public:
  explicit OsmNodeTable(const GeoAnchor& anchor) : anchor_(anchor) {}

  int64_t NextId() { return next_id_--; }

  // World metres (x, y) on OSM's grid: longitude and latitude in units of
  // 10^-7 degree, not yet rounded. Throws InputError for coordinates that are
  // not finite or that lie off the globe from the anchor.
  GridPosition GridPositionOf(double x_m, double y_m) const;

  // The node at a grid point, made on first use.
  int64_t NodeAt(const GridPoint& point);
  // The node nearest to world metres (x, y).
  int64_t NodeAt(double x_m, double y_m);

  // A node at the anchor itself with `tags`.
  void AddAnchorNode(const std::string& tags);

  // Every <node> made so far, in order.
  const std::string& xml() const { return xml_; }

 private:
  GeoAnchor anchor_;
  int64_t next_id_ = -1;
  std::map<GridPoint, int64_t> ids_;
  std::string xml_;
};

}  // namespace areagraph

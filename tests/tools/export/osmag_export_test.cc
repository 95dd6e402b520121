// osmAG XML and its metre -> latitude/longitude conversion.
#include "tools/export/osmag_export.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <regex>
#include <set>
#include <string>
#include <vector>

#include "common/error.h"
#include "tests/support/test_support.h"
#include "tests/tools/export/test_area_graph.h"

namespace areagraph {
namespace {

TEST(MetresToLatLon, LocalTangentPlane) {
  const GeoAnchor anchor{30.0, 120.0};
  const LatLon origin = MetresToLatLon(anchor, 0, 0);
  EXPECT_DOUBLE_EQ(origin.lat_deg, 30.0);
  EXPECT_DOUBLE_EQ(origin.lon_deg, 120.0);
  // One degree of latitude is R * pi / 180 = 111319.49 m; of longitude at
  // 30 deg, cos(30 deg) times that.
  const double metres_per_degree = 6378137.0 * 3.14159265358979323846 / 180.0;
  const LatLon north = MetresToLatLon(anchor, 0, metres_per_degree);
  EXPECT_NEAR(north.lat_deg, 31.0, 1e-12);
  EXPECT_DOUBLE_EQ(north.lon_deg, 120.0);
  const LatLon east = MetresToLatLon(anchor, metres_per_degree * std::sqrt(3.0) / 2, 0);
  EXPECT_NEAR(east.lon_deg, 121.0, 1e-12);
  EXPECT_DOUBLE_EQ(east.lat_deg, 30.0);
}

// Everything matching `pattern`'s first group, in order.
std::vector<std::string> AllMatches(const std::string& text, const std::string& pattern) {
  std::vector<std::string> found;
  const std::regex expression(pattern);
  for (auto it = std::sregex_iterator(text.begin(), text.end(), expression);
       it != std::sregex_iterator(); ++it) {
    found.push_back((*it)[1]);
  }
  return found;
}

// The blocks of one element type (<way ...>...</way>), in order.
std::vector<std::string> Blocks(const std::string& xml, const std::string& element) {
  std::vector<std::string> blocks;
  const std::regex block("<" + element + " [^>]*>[\\s\\S]*?</" + element + ">");
  for (auto it = std::sregex_iterator(xml.begin(), xml.end(), block); it != std::sregex_iterator();
       ++it) {
    blocks.push_back(it->str());
  }
  return blocks;
}

std::vector<std::string> NodeRefs(const std::string& way) {
  return AllMatches(way, "<nd ref=\"(-?\\d+)\"/>");
}

bool Has(const std::vector<std::string>& refs, const std::string& ref) {
  return std::count(refs.begin(), refs.end(), ref) > 0;
}

bool HasTag(const std::string& block, const std::string& key, const std::string& value) {
  return block.find("<tag k=\"" + key + "\" v=\"" + value + "\"/>") != std::string::npos;
}

TEST(OsmAgExport, SharesNodesAndOrdersWays) {
  const std::string xml = AreaGraphToOsmAg(testing::TwoRoomAreaGraph(), {"house", GeoAnchor()});
  EXPECT_EQ(xml.rfind("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n", 0), 0u);
  EXPECT_NE(xml.find("<osm version=\"0.6\" generator=\"areagraph\" upload=\"never\">"),
            std::string::npos);
  // Root + 6 distinct square corners (2 shared) + 3 border points + 4 hole
  // corners + 4 structure corners.
  const std::vector<std::string> node_ids = AllMatches(xml, "<node id=\"(-?\\d+)\"");
  EXPECT_EQ(node_ids.size(), 18u);
  EXPECT_EQ(node_ids.front(), "-1");
  // OSM's precision: 7 decimals. A graph without stable ids says so.
  EXPECT_NE(xml.find("lat=\"31.1794700\" lon=\"121.5904200\">\n"
                     "    <tag k=\"areagraph:ids\" v=\"index\"/>\n"
                     "    <tag k=\"name\" v=\"root\"/>"),
            std::string::npos)
      << xml;
  // Area 1 has a hole, so it is a multipolygon relation, written last.
  const std::vector<std::string> names = AllMatches(xml, "<tag k=\"name\" v=\"([^\"]+)\"");
  EXPECT_EQ(names, (std::vector<std::string>{"root", "house", "area_0", "passage_0", "area_1"}));
  const std::vector<std::string> way_ids = AllMatches(xml, "<way id=\"(-?\\d+)\"");
  ASSERT_EQ(way_ids.size(), 5u);  // structure, area 0, area 1's two rings, passage
  const std::vector<std::string> relation_ids = AllMatches(xml, "<relation id=\"(-?\\d+)\"");
  ASSERT_EQ(relation_ids.size(), 1u);
  std::set<std::string> ids(node_ids.begin(), node_ids.end());
  ids.insert(way_ids.begin(), way_ids.end());
  ids.insert(relation_ids.begin(), relation_ids.end());
  EXPECT_EQ(ids.size(), 24u);  // unique across nodes, ways and relations
  for (const std::string& id : ids) EXPECT_LT(std::stoi(id), 0);
  // The passage's 3 border points join both squares: structure 5, squares
  // 5 + 3 each, the hole 5, passage 3.
  EXPECT_EQ(AllMatches(xml, "<nd ref=\"(-?\\d+)\"").size(), 29u);
  EXPECT_EQ(AllMatches(xml, "<tag k=\"osmAG:parent\" v=\"(house)\"").size(), 2u);
  EXPECT_EQ(AllMatches(xml, "<tag k=\"level\" v=\"(0)\"").size(), 4u);
  EXPECT_EQ(xml.find("\"height\""), std::string::npos);
}

TEST(OsmAgExport, AnAreaWithHolesIsAMultipolygonOfUntaggedRings) {
  const std::string xml = AreaGraphToOsmAg(testing::TwoRoomAreaGraph(), {"house", GeoAnchor()});
  const std::vector<std::string> ways = Blocks(xml, "way");
  ASSERT_EQ(ways.size(), 5u);
  const std::string relation = Blocks(xml, "relation").at(0);
  EXPECT_EQ(AllMatches(relation, "<member type=\"way\" ref=\"(-\\d+)\" role=\"outer\"/>"),
            AllMatches(ways[2], "<way id=\"(-\\d+)\""));
  EXPECT_EQ(AllMatches(relation, "<member type=\"way\" ref=\"(-\\d+)\" role=\"inner\"/>"),
            AllMatches(ways[3], "<way id=\"(-\\d+)\""));
  for (const char* tag : {"<tag k=\"type\" v=\"multipolygon\"/>", "<tag k=\"name\" v=\"area_1\"/>",
                          "<tag k=\"osmAG:type\" v=\"area\"/>", "<tag k=\"indoor\" v=\"room\"/>"}) {
    EXPECT_NE(relation.find(tag), std::string::npos) << tag;
  }
  // The rings carry no tags: the relation is the area.
  EXPECT_EQ(ways[2].find("<tag "), std::string::npos);
  EXPECT_EQ(ways[3].find("<tag "), std::string::npos);
  EXPECT_EQ(NodeRefs(ways[2]).size(), 8u);  // 4 corners, 3 border points, closed
  EXPECT_EQ(NodeRefs(ways[3]).size(), 5u);  // the hole
}

// A passage whose border lies on a hole joins the hole's ring, which is where
// its nodes belong; put into the outer ring it made that ring cross itself
// (lab_a's corridor loop: 132 m2 of overlap with the rooms it circles).
TEST(OsmAgExport, PassageOnAHoleJoinsTheInnerRing) {
  proto::AreaGraph graph = testing::TwoRoomAreaGraph();
  // A room filling the corridor's hole, and a passage along the hole's left
  // edge (x = 16 px, y 6..8 px) through a point that is no vertex yet.
  proto::Area* inside = graph.add_areas();
  inside->set_id(2);
  const proto::Ring& hole_m = graph.areas(1).polygon_m().holes(0);
  *inside->mutable_polygon_m()->mutable_outer() = hole_m;
  *inside->mutable_polygon_px()->mutable_outer() = graph.areas(1).polygon_px().holes(0);
  proto::Passage* passage = graph.add_passages();
  passage->set_id(1);
  passage->set_area_a(1);
  passage->set_area_b(2);
  passage->set_width_m(0.1);
  const double x = hole_m.points(0).x();  // the hole's left edge in metres
  for (const double y : {hole_m.points(0).y(), (hole_m.points(0).y() + hole_m.points(2).y()) / 2,
                         hole_m.points(2).y()}) {
    proto::Point2* point = passage->add_border_m();
    point->set_x(x);
    point->set_y(y);
  }
  const std::string xml = AreaGraphToOsmAg(graph, {"house", GeoAnchor()});
  const std::vector<std::string> ways = Blocks(xml, "way");
  ASSERT_EQ(ways.size(), 7u);  // structure, area 0, area 1's rings, area 2, passages
  const std::vector<std::string> outer = NodeRefs(ways[2]), inner = NodeRefs(ways[3]);
  const std::vector<std::string> room = NodeRefs(ways[4]), line = NodeRefs(ways[6]);
  ASSERT_TRUE(HasTag(ways[6], "name", "passage_1"));
  ASSERT_EQ(line.size(), 3u);
  for (const std::string& node : line) {
    EXPECT_TRUE(Has(inner, node)) << node;
    EXPECT_TRUE(Has(room, node)) << node;
    EXPECT_FALSE(Has(outer, node)) << node;
  }
  EXPECT_EQ(outer.size(), 8u);  // unchanged: 4 corners, 3 points of passage 0, closed
  EXPECT_EQ(inner.size(), 6u);  // 4 corners, the new point, closed
}

// Vertices closer than OSM's precision (7 decimals, about a centimetre)
// become one node. Where the outline comes back within that distance of
// itself (a neck 1 mm wide here) the node would be visited twice, which JOSM
// reports as a self-intersecting way: the outline is cut there into two
// rings of a multipolygon that share the node.
TEST(OsmAgExport, ANeckNarrowerThanOsmPrecisionSplitsTheOutline) {
  proto::AreaGraph graph;
  graph.set_format_version(1);
  proto::Area* area = graph.add_areas();
  area->set_id(0);
  for (const auto& [x, y] : std::vector<std::pair<double, double>>{
           {0, 0}, {1, 0.4995}, {2, 0}, {2, 1}, {1, 0.5005}, {0, 1}}) {
    proto::Point2* point = area->mutable_polygon_m()->mutable_outer()->add_points();
    point->set_x(x);
    point->set_y(y);
  }
  const std::string xml = AreaGraphToOsmAg(graph, {"neck", GeoAnchor()});
  const std::vector<std::string> relations = Blocks(xml, "relation");
  ASSERT_EQ(relations.size(), 1u) << xml;
  EXPECT_EQ(AllMatches(relations[0], "role=\"(outer)\"").size(), 2u);
  EXPECT_EQ(AllMatches(relations[0], "role=\"(inner)\"").size(), 0u);
  const std::vector<std::string> ways = Blocks(xml, "way");
  ASSERT_EQ(ways.size(), 3u);  // structure and the two loops
  std::set<std::string> shared;
  for (int i = 1; i < 3; ++i) {
    std::vector<std::string> refs = NodeRefs(ways[i]);
    EXPECT_EQ(refs.size(), 4u);  // triangles, closed
    refs.pop_back();
    EXPECT_EQ(std::set<std::string>(refs.begin(), refs.end()).size(), 3u);  // no node twice
    for (const std::string& ref : refs) {
      if (Has(NodeRefs(ways[3 - i]), ref)) shared.insert(ref);
    }
  }
  EXPECT_EQ(shared.size(), 1u);  // the neck
}

TEST(OsmAgExport, NamesAndReferencesUseTheStableIdsOfAMatchedGraph) {
  proto::AreaGraph graph = testing::TwoRoomAreaGraph();
  const std::string unmatched = AreaGraphToOsmAg(graph, {"house", GeoAnchor()});
  EXPECT_EQ(unmatched.find("areagraph:stable_id"), std::string::npos);
  graph.mutable_version()->set_number(3);
  graph.mutable_areas(0)->set_stable_id(7);
  graph.mutable_areas(1)->set_stable_id(2);
  graph.mutable_passages(0)->set_stable_id(11);
  const std::string xml = AreaGraphToOsmAg(graph, {"house", GeoAnchor()});
  // Area 0's way, the passage, then area 1's relation.
  EXPECT_EQ(AllMatches(xml, "<tag k=\"areagraph:stable_id\" v=\"(\\d+)\"/>"),
            (std::vector<std::string>{"7", "11", "2"}));
  EXPECT_EQ(AllMatches(xml, "<tag k=\"areagraph:index\" v=\"(\\d+)\"/>"),
            (std::vector<std::string>{"0", "0", "1"}));
  EXPECT_EQ(AllMatches(xml, "<tag k=\"name\" v=\"([^\"]+)\"/>"),
            (std::vector<std::string>{"root", "house", "area_7", "passage_11", "area_2"}));
  EXPECT_NE(xml.find("<tag k=\"osmAG:from\" v=\"area_7\"/>\n"
                     "    <tag k=\"osmAG:to\" v=\"area_2\"/>"),
            std::string::npos)
      << xml;
  EXPECT_NE(xml.find("<tag k=\"areagraph:ids\" v=\"stable\"/>"), std::string::npos);
}

// osmAG's passage tags and nothing that JOSM reads as a door node on a way
// (indoor=door, door=*, width); the width is kept as areagraph:width.
TEST(OsmAgExport, PassagesCarryNoDoorTags) {
  const std::string xml = AreaGraphToOsmAg(testing::TwoRoomAreaGraph(), {"house", GeoAnchor()});
  const std::string passage = Blocks(xml, "way").at(4);
  ASSERT_TRUE(HasTag(passage, "osmAG:type", "passage"));
  EXPECT_TRUE(HasTag(passage, "osmAG:from", "area_0"));
  EXPECT_TRUE(HasTag(passage, "osmAG:to", "area_1"));
  EXPECT_TRUE(HasTag(passage, "areagraph:width", "0.300"));
  for (const char* key : {"\"indoor\"", "\"door\"", "\"width\""}) {
    EXPECT_EQ(passage.find(std::string("k=") + key), std::string::npos) << key;
  }
}

TEST(OsmAgExport, WritesLevelAndHeightWhenGiven) {
  OsmAgSettings settings{"house", GeoAnchor()};
  settings.level = -1;
  settings.height_m = 3.25;
  const std::string xml = AreaGraphToOsmAg(testing::TwoRoomAreaGraph(), settings);
  EXPECT_EQ(AllMatches(xml, "<tag k=\"level\" v=\"(-1)\"").size(), 4u);
  EXPECT_EQ(AllMatches(xml, "<tag k=\"height\" v=\"(3.250)\"").size(), 2u);
}

// Older graphs have no border_m: the passage runs along segment_m, whose ends
// become nodes of both outlines.
TEST(OsmAgExport, PassageWithoutBorderPutsItsEndsIntoBothOutlines) {
  proto::AreaGraph graph = testing::TwoRoomAreaGraph();
  graph.mutable_passages(0)->clear_border_m();
  const std::string xml = AreaGraphToOsmAg(graph, {"house", GeoAnchor()});
  const std::vector<std::string> ways = Blocks(xml, "way");
  ASSERT_EQ(ways.size(), 5u);  // structure, area 0, area 1's two rings, passage
  const std::vector<std::string> room = NodeRefs(ways[1]), corridor = NodeRefs(ways[2]);
  const std::vector<std::string> line = NodeRefs(ways[4]);
  EXPECT_EQ(room.size(), 7u);  // 4 corners + 2 passage ends + the closing repeat
  EXPECT_EQ(corridor.size(), 7u);
  ASSERT_EQ(line.size(), 2u);
  for (const std::string& end : line) {
    EXPECT_EQ(std::count(room.begin(), room.end(), end), 1);
    EXPECT_EQ(std::count(corridor.begin(), corridor.end(), end), 1);
  }
}

// A passage whose areas share no border holds the obstacles on either side
// of the opening; those points lie on no outline, and bending the outlines
// out to them made areas overlap (lab_ipa_furnitures).
TEST(OsmAgExport, PassageEndsOffTheOutlinesLeaveTheOutlinesAlone) {
  proto::AreaGraph graph = testing::TwoRoomAreaGraph();
  proto::Passage* passage = graph.mutable_passages(0);
  passage->clear_border_m();
  passage->mutable_segment_m()->mutable_a()->set_x(passage->segment_m().a().x() - 0.02);
  const std::string xml = AreaGraphToOsmAg(graph, {"house", GeoAnchor()});
  const std::vector<std::string> ways = Blocks(xml, "way");
  ASSERT_EQ(ways.size(), 5u);
  const std::vector<std::string> line = NodeRefs(ways[4]);
  ASSERT_EQ(line.size(), 2u);
  // End b lies on the shared edge and joins both; end a, 2 cm into area 0,
  // joins neither.
  EXPECT_FALSE(Has(NodeRefs(ways[1]), line[0]));
  EXPECT_FALSE(Has(NodeRefs(ways[2]), line[0]));
  EXPECT_TRUE(Has(NodeRefs(ways[1]), line[1]));
  EXPECT_TRUE(Has(NodeRefs(ways[2]), line[1]));
  EXPECT_EQ(NodeRefs(ways[1]).size(), 6u);
}

TEST(OsmAgExport, EscapesTheMapName) {
  const std::string xml = AreaGraphToOsmAg(testing::TwoRoomAreaGraph(), {"a<b&\"c\"", GeoAnchor()});
  EXPECT_NE(xml.find("v=\"a&lt;b&amp;&quot;c&quot;\""), std::string::npos);
}

TEST(OsmAgExport, RejectsDegenerateAreas) {
  proto::AreaGraph graph = testing::TwoRoomAreaGraph();
  graph.mutable_areas(0)->mutable_polygon_m()->mutable_outer()->mutable_points()->RemoveLast();
  graph.mutable_areas(0)->mutable_polygon_m()->mutable_outer()->mutable_points()->RemoveLast();
  EXPECT_THROW(AreaGraphToOsmAg(graph, {"house", GeoAnchor()}), InputError);
}

// The graph moved by (dx, dy) metres, as a far map origin would place it.
proto::AreaGraph ShiftedAreaGraph(double dx, double dy) {
  proto::AreaGraph graph = testing::TwoRoomAreaGraph();
  for (proto::Area& area : *graph.mutable_areas()) {
    for (proto::Point2& point : *area.mutable_polygon_m()->mutable_outer()->mutable_points()) {
      point.set_x(point.x() + dx);
      point.set_y(point.y() + dy);
    }
  }
  for (proto::Passage& passage : *graph.mutable_passages()) {
    for (proto::Point2* end :
         {passage.mutable_segment_m()->mutable_a(), passage.mutable_segment_m()->mutable_b()}) {
      end->set_x(end->x() + dx);
      end->set_y(end->y() + dy);
    }
  }
  return graph;
}

// The case: an origin of 1.7e308 m used to give node lines cut off
// by a fixed buffer. Off the globe is refused; far but on the globe is whole.
TEST(OsmAgExport, PointsOffTheGlobeAreRefusedAndFarOnesStayWellFormed) {
  for (const double far : {1.7e308, -1e8, 2.5e7}) {
    const std::string error = testing::ErrorOf<InputError>([&] {
      AreaGraphToOsmAg(ShiftedAreaGraph(0, far), {"house", GeoAnchor()});
    });
    EXPECT_NE(error.find("lies off the globe"), std::string::npos) << far << ": " << error;
  }
  const std::string xml = AreaGraphToOsmAg(ShiftedAreaGraph(5e5, -3e6), {"house", GeoAnchor()});
  const std::vector<std::string> nodes = AllMatches(xml, "(<node [^\n]*)\n");
  ASSERT_GE(nodes.size(), 9u);  // root, structure corners, area vertices
  const std::regex whole(
      "<node id=\"-\\d+\" visible=\"true\" lat=\"-?\\d+\\.\\d{7}\" "
      "lon=\"-?\\d+\\.\\d{7}\"/?>");
  for (const std::string& node : nodes) EXPECT_TRUE(std::regex_match(node, whole)) << node;
}

TEST(OsmAgExport, NonFiniteAndAbsurdAnchorsAreRefused) {
  const double nan = std::nan(""), inf = INFINITY;
  for (const double bad : {nan, inf, -inf, 1e308, -1e308, 90.0, -89.5}) {
    EXPECT_NE(testing::ErrorOf<OptionsError>([&] {
                CheckGeoAnchor({bad, 0});
              }).find("--anchor-lat"),
              std::string::npos)
        << bad;
  }
  for (const double bad : {nan, inf, -inf, 1e308, -1e308, 180.5}) {
    EXPECT_NE(testing::ErrorOf<OptionsError>([&] {
                CheckGeoAnchor({0, bad});
              }).find("--anchor-lon"),
              std::string::npos)
        << bad;
  }
  EXPECT_EQ(testing::ErrorOf<OptionsError>([&] { CheckGeoAnchor({-89, 180}); }), "");
}

}  // namespace
}  // namespace areagraph

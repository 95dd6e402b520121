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

TEST(OsmAgExport, SharesNodesAndOrdersWays) {
  const std::string xml = AreaGraphToOsmAg(testing::TwoRoomAreaGraph(), {"house", GeoAnchor()});
  EXPECT_EQ(xml.rfind("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n", 0), 0u);
  EXPECT_NE(xml.find("<osm version=\"0.6\" generator=\"areagraph\" upload=\"never\">"),
            std::string::npos);
  // Root + 6 distinct square corners (2 shared) + 3 border points + 4
  // structure corners.
  const std::vector<std::string> node_ids = AllMatches(xml, "<node id=\"(-?\\d+)\"");
  EXPECT_EQ(node_ids.size(), 14u);
  EXPECT_EQ(node_ids.front(), "-1");
  EXPECT_NE(xml.find("lat=\"31.1794700000\" lon=\"121.5904200000\">\n"
                     "    <tag k=\"name\" v=\"root\"/>"),
            std::string::npos)
      << xml;
  const std::vector<std::string> names = AllMatches(xml, "<tag k=\"name\" v=\"([^\"]+)\"");
  EXPECT_EQ(names, (std::vector<std::string>{"root", "house", "area_0", "area_1", "passage_0"}));
  const std::vector<std::string> way_ids = AllMatches(xml, "<way id=\"(-?\\d+)\"");
  ASSERT_EQ(way_ids.size(), 4u);
  std::set<std::string> ids(node_ids.begin(), node_ids.end());
  ids.insert(way_ids.begin(), way_ids.end());
  EXPECT_EQ(ids.size(), 18u);  // unique across nodes and ways
  for (const std::string& id : ids) EXPECT_LT(std::stoi(id), 0);
  // The holes of area 1 are not written; the passage's 3 border points join
  // both squares: structure 5, squares 5 + 3 each, passage 3.
  EXPECT_EQ(AllMatches(xml, "<nd ref=\"(-?\\d+)\"").size(), 24u);
  EXPECT_EQ(AllMatches(xml, "<tag k=\"osmAG:parent\" v=\"(house)\"").size(), 2u);
  EXPECT_EQ(AllMatches(xml, "<tag k=\"level\" v=\"(0)\"").size(), 4u);
  EXPECT_EQ(xml.find("\"height\""), std::string::npos);
}

TEST(OsmAgExport, TagsTheStableIdsOfAMatchedGraphOnly) {
  proto::AreaGraph graph = testing::TwoRoomAreaGraph();
  const std::string unmatched = AreaGraphToOsmAg(graph, {"house", GeoAnchor()});
  EXPECT_EQ(unmatched.find("areagraph:stable_id"), std::string::npos);
  graph.mutable_version()->set_number(3);
  graph.mutable_areas(0)->set_stable_id(7);
  graph.mutable_areas(1)->set_stable_id(2);
  graph.mutable_passages(0)->set_stable_id(11);
  const std::string xml = AreaGraphToOsmAg(graph, {"house", GeoAnchor()});
  EXPECT_EQ(AllMatches(xml, "<tag k=\"areagraph:stable_id\" v=\"(\\d+)\"/>"),
            (std::vector<std::string>{"7", "2", "11"}));
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
  std::vector<std::vector<std::string>> ways;
  const std::regex way("<way [^>]*>([\\s\\S]*?)</way>");
  for (auto it = std::sregex_iterator(xml.begin(), xml.end(), way); it != std::sregex_iterator();
       ++it) {
    const std::string body = (*it)[1];
    ways.push_back(AllMatches(body, "<nd ref=\"(-?\\d+)\"/>"));
  }
  ASSERT_EQ(ways.size(), 4u);     // structure, two areas, passage
  EXPECT_EQ(ways[1].size(), 7u);  // 4 corners + 2 passage ends + the closing repeat
  EXPECT_EQ(ways[2].size(), 7u);
  ASSERT_EQ(ways[3].size(), 2u);
  for (const std::string& end : ways[3]) {
    EXPECT_EQ(std::count(ways[1].begin(), ways[1].end(), end), 1);
    EXPECT_EQ(std::count(ways[2].begin(), ways[2].end(), end), 1);
  }
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
      "<node id=\"-\\d+\" visible=\"true\" lat=\"-?\\d+\\.\\d{10}\" "
      "lon=\"-?\\d+\\.\\d{10}\"/?>");
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

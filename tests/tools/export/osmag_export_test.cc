// osmAG XML and its metre -> latitude/longitude conversion.
#include "tools/export/osmag_export.h"

#include <gtest/gtest.h>

#include <cmath>
#include <regex>
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
  const std::string xml = AreaGraphToOsmAg(testing::TwoRoomAreaGraph(), "house", GeoAnchor());
  EXPECT_EQ(xml.rfind("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n", 0), 0u);
  EXPECT_NE(xml.find("<osm version=\"0.6\" generator=\"areagraph\">"), std::string::npos);
  // Root + 6 distinct square corners (2 shared) + 2 passage ends.
  const std::vector<std::string> node_ids = AllMatches(xml, "<node id=\"(-?\\d+)\"");
  EXPECT_EQ(node_ids.size(), 9u);
  EXPECT_EQ(node_ids.front(), "-1");
  EXPECT_NE(xml.find("lat=\"31.1794700000\" lon=\"121.5904200000\">\n"
                     "    <tag k=\"name\" v=\"root\"/>"),
            std::string::npos)
      << xml;
  const std::vector<std::string> names = AllMatches(xml, "<tag k=\"name\" v=\"([^\"]+)\"");
  EXPECT_EQ(names, (std::vector<std::string>{"root", "area_0", "area_1", "passage_0"}));
  const std::vector<std::string> way_ids = AllMatches(xml, "<way id=\"(-?\\d+)\"");
  EXPECT_EQ(way_ids, (std::vector<std::string>{"-10", "-11", "-12"}));
  // The holes of area 1 are not written: 5 + 5 + 2 node references.
  EXPECT_EQ(AllMatches(xml, "<nd ref=\"(-?\\d+)\"").size(), 12u);
}

TEST(OsmAgExport, EscapesTheMapName) {
  const std::string xml = AreaGraphToOsmAg(testing::TwoRoomAreaGraph(), "a<b&\"c\"", GeoAnchor());
  EXPECT_NE(xml.find("v=\"a&lt;b&amp;&quot;c&quot;\""), std::string::npos);
}

TEST(OsmAgExport, RejectsDegenerateAreas) {
  proto::AreaGraph graph = testing::TwoRoomAreaGraph();
  graph.mutable_areas(0)->mutable_polygon_m()->mutable_outer()->mutable_points()->RemoveLast();
  graph.mutable_areas(0)->mutable_polygon_m()->mutable_outer()->mutable_points()->RemoveLast();
  EXPECT_THROW(AreaGraphToOsmAg(graph, "house", GeoAnchor()), InputError);
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
    const std::string error = testing::ErrorOf<InputError>(
        [&] { AreaGraphToOsmAg(ShiftedAreaGraph(0, far), "house", GeoAnchor()); });
    EXPECT_NE(error.find("lies off the globe"), std::string::npos) << far << ": " << error;
  }
  const std::string xml = AreaGraphToOsmAg(ShiftedAreaGraph(5e5, -3e6), "house", GeoAnchor());
  const std::vector<std::string> nodes = AllMatches(xml, "(<node [^\n]*)\n");
  ASSERT_EQ(nodes.size(), 9u);
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

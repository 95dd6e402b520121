// Exports key areas and passages by the match stage's stable ids, which a
// re-run keeps, and keep the index beside them; a graph without stable ids
// (ag-merge's) keeps its indices and says so. Numbers carry no float noise.
#include "tools/export/export_ids.h"

#include <gtest/gtest.h>

#include <opencv2/core.hpp>
#include <string>

#include "common/error.h"
#include "tests/tools/export/test_area_graph.h"
#include "tools/export/area_label_image.h"
#include "tools/export/geojson_export.h"
#include "tools/export/json_text.h"
#include "tools/export/node_link_json.h"

namespace areagraph {
namespace {

// TwoRoomAreaGraph as ag-match writes it: areas 0 and 1 are 7 and 2,
// passage 0 is 11.
proto::AreaGraph MatchedGraph() {
  proto::AreaGraph graph = testing::TwoRoomAreaGraph();
  graph.mutable_version()->set_number(3);
  graph.mutable_areas(0)->set_stable_id(7);
  graph.mutable_areas(1)->set_stable_id(2);
  graph.mutable_passages(0)->set_stable_id(11);
  return graph;
}

bool Contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

TEST(ExportIds, AreStableIdsWhenTheGraphHasThem) {
  const ExportIds matched(MatchedGraph());
  EXPECT_TRUE(matched.stable());
  EXPECT_EQ(matched.Of(MatchedGraph().areas(0)), 7);
  EXPECT_EQ(matched.Of(MatchedGraph().passages(0)), 11);
  EXPECT_EQ(matched.OfArea(1), 2);
  EXPECT_EQ(IdsKindName(matched), "stable");
  const ExportIds merged(testing::TwoRoomAreaGraph());
  EXPECT_FALSE(merged.stable());
  EXPECT_EQ(merged.OfArea(1), 1);
  EXPECT_EQ(IdsKindName(merged), "index");
  EXPECT_THROW(merged.OfArea(5), InputError);
}

TEST(ExportIds, RefuseTwoAreasWithOneId) {
  proto::AreaGraph graph = MatchedGraph();
  graph.mutable_areas(1)->set_stable_id(7);
  EXPECT_THROW(ExportIds{graph}, InputError);
}

TEST(ExportIds, KeyGeoJsonFeaturesAndTheirReferences) {
  const std::string geojson = AreaGraphToGeoJson(MatchedGraph(), {"house"});
  EXPECT_TRUE(Contains(geojson, "\"ids\":\"stable\"")) << geojson;
  EXPECT_TRUE(Contains(geojson, "\"id\":\"area/7\"")) << geojson;
  EXPECT_TRUE(Contains(geojson, "\"area_id\":2,\"stable_id\":2,\"index\":1,")) << geojson;
  EXPECT_TRUE(Contains(geojson, "\"name\":\"area_2\"")) << geojson;
  EXPECT_TRUE(Contains(geojson, "\"id\":\"passage/11\"")) << geojson;
  EXPECT_TRUE(Contains(geojson, "\"from\":7,\"to\":2}")) << geojson;
  const std::string merged = AreaGraphToGeoJson(testing::TwoRoomAreaGraph(), {"house"});
  EXPECT_TRUE(Contains(merged, "\"ids\":\"index\"")) << merged;
  EXPECT_TRUE(Contains(merged, "\"area_id\":1,\"index\":1,")) << merged;
}

TEST(ExportIds, KeyNetworkxNodesAndEdges) {
  const std::string json = AreaGraphToNodeLinkJson(MatchedGraph(), "house");
  EXPECT_TRUE(Contains(json, "\"ids\":\"stable\"")) << json;
  EXPECT_TRUE(Contains(json, "{\"id\":7,\"stable_id\":7,\"index\":0,\"name\":\"area_7\"")) << json;
  EXPECT_TRUE(Contains(json,
                       "{\"source\":7,\"target\":2,\"key\":11,\"id\":11,\"stable_id\":11,"
                       "\"index\":0,\"name\":\"passage_11\""))
      << json;
}

TEST(ExportIds, LabelTheLabelImage) {
  const cv::Mat labels = AreaLabelImage(MatchedGraph());
  EXPECT_EQ(cv::countNonZero(labels == 8), 100);  // area 7
  EXPECT_EQ(cv::countNonZero(labels == 3), 96);   // area 2
  EXPECT_EQ(cv::countNonZero(labels == 1), 0);
}

TEST(ExportNumbers, AreRoundedWithoutFloatNoise) {
  EXPECT_EQ(JsonNumber(16.650000000000002, kMetreDecimals), "16.65");
  EXPECT_EQ(JsonNumber(0.1 + 0.2, kMetreDecimals), "0.3");
  EXPECT_EQ(JsonNumber(-0.0004, kMetreDecimals), "0");
  EXPECT_EQ(JsonNumber(2.0, kMetreDecimals), "2");
  EXPECT_EQ(JsonNumber(121.590421234567, kDegreeDecimals), "121.59042123");
  EXPECT_EQ(JsonNumber(1e300, kMetreDecimals), "1e+300");
  // Every coordinate of the test graph's GeoJSON has at most 3 decimals.
  proto::AreaGraph graph = testing::TwoRoomAreaGraph();
  graph.mutable_areas(0)->set_area_m2(0.1 + 0.2);
  const std::string geojson = AreaGraphToGeoJson(graph, {"house"});
  EXPECT_TRUE(Contains(geojson, "\"area_m2\":0.3,")) << geojson;
  EXPECT_FALSE(Contains(geojson, "0000")) << geojson;
}

}  // namespace
}  // namespace areagraph

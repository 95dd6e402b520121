// ag-export end to end: an Area Graph written to a store as the merge stage's
// head artifact, exported in every format and read back.
#include <google/protobuf/struct.pb.h>
#include <google/protobuf/util/json_util.h>
#include <google/protobuf/util/message_differencer.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <regex>
#include <string>
#include <vector>

#include "proto/pipeline_options.pb.h"
#include "stages/pipeline/stage.h"
#include "store/artifact_store.h"
#include "tests/support/test_support.h"
#include "tests/tools/export/test_area_graph.h"
#include "tools/export/geo_anchor.h"

namespace areagraph {
namespace {

using google::protobuf::Struct;
using google::protobuf::Value;
using testing::CountLines;
using testing::ReadFile;
using testing::RunTool;
using testing::TempDir;

class AgExportCli : public ::testing::Test {
 protected:
  void SetUp() override {
    std::unique_ptr<ArtifactStore> store = OpenArtifactStore(store_path_);
    StageInputs inputs;
    inputs.digests = {"cut-artifact-digest"};
    RunCachedStage(*store, "house", StageOf(kMergeStage), {}, inputs,
                   [] { return std::make_unique<proto::AreaGraph>(testing::TwoRoomAreaGraph()); });
  }

  testing::CommandResult Export(const std::string& format, const std::string& out,
                                std::vector<std::string> extra = {}) {
    std::vector<std::string> args = {"--store",  store_path_, "--map", "house",
                                     "--format", format,      "--out", out};
    args.insert(args.end(), extra.begin(), extra.end());
    return RunTool("ag-export", args);
  }

  TempDir dir_;
  const std::string store_path_ = dir_.File("areagraph.db");
};

TEST_F(AgExportCli, LabelImageHasTheMapSizeAndOneLabelPerArea) {
  const auto run = Export("labels", dir_.File("labels.png"));
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const cv::Mat labels = cv::imread(dir_.File("labels.png"), cv::IMREAD_UNCHANGED);
  ASSERT_EQ(labels.type(), CV_16U);
  EXPECT_EQ(labels.size(), cv::Size(40, 20));
  EXPECT_EQ(cv::countNonZero(labels == 1), 100);
  EXPECT_EQ(cv::countNonZero(labels == 2), 96);
  EXPECT_EQ(cv::countNonZero(labels == 0), 800 - 196);
}

// The kinds file names each label of the label image (area id + 1).
TEST_F(AgExportCli, KindsNameEachLabel) {
  const auto run = Export("kinds", dir_.File("labels.kinds.tsv"));
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_EQ(ReadFile(dir_.File("labels.kinds.tsv")), "label\tkind\n1\troom\n2\tcorridor\n");
}

double Number(const Value& value) { return value.number_value(); }

// The JSON file at `path` as a Struct; a failure when it does not parse.
Struct ReadJson(const std::string& path) {
  Struct parsed;
  EXPECT_TRUE(google::protobuf::util::JsonStringToMessage(ReadFile(path), &parsed).ok()) << path;
  return parsed;
}

// Twice the signed area of a closed GeoJSON ring.
double TwiceSignedArea(const google::protobuf::ListValue& ring) {
  double sum = 0;
  for (int i = 0; i + 1 < ring.values_size(); ++i) {
    const auto& a = ring.values(i).list_value();
    const auto& b = ring.values(i + 1).list_value();
    sum += Number(a.values(0)) * Number(b.values(1)) - Number(b.values(0)) * Number(a.values(1));
  }
  return sum;
}

TEST_F(AgExportCli, GeoJsonParsesWithClosedOrientedRings) {
  const auto run = Export("geojson", dir_.File("map.geojson"));
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const Struct collection = ReadJson(dir_.File("map.geojson"));
  EXPECT_EQ(collection.fields().at("type").string_value(), "FeatureCollection");
  EXPECT_EQ(collection.fields().at("name").string_value(), "house");
  EXPECT_EQ(collection.fields().at("units").string_value(), "metres");
  EXPECT_EQ(Number(collection.fields().at("frame").struct_value().fields().at("width_px")), 40);
  const auto& features = collection.fields().at("features").list_value();
  ASSERT_EQ(features.values_size(), 3);

  const Struct& corridor = features.values(1).struct_value();
  EXPECT_EQ(corridor.fields().at("id").string_value(), "area/1");
  const Struct& geometry = corridor.fields().at("geometry").struct_value();
  EXPECT_EQ(geometry.fields().at("type").string_value(), "Polygon");
  const auto& rings = geometry.fields().at("coordinates").list_value();
  ASSERT_EQ(rings.values_size(), 2);  // outer ring and the hole
  const auto& outer = rings.values(0).list_value();
  ASSERT_EQ(outer.values_size(), 5);
  EXPECT_EQ(outer.values(0).DebugString(), outer.values(4).DebugString());
  // 10x10 px at 0.05 m = 0.25 m2, counter-clockwise; the 2x2 px hole clockwise.
  EXPECT_NEAR(TwiceSignedArea(outer) / 2, 0.25, 1e-12);
  EXPECT_NEAR(TwiceSignedArea(rings.values(1).list_value()) / 2, -0.01, 1e-12);
  // Pixel (12, 2) is world (1 + 12 * 0.05, 2 + (20 - 2) * 0.05) = (1.6, 2.9).
  bool found_corner = false;
  for (const Value& position : outer.values()) {
    const auto& xy = position.list_value();
    found_corner |=
        std::abs(Number(xy.values(0)) - 1.6) < 1e-9 && std::abs(Number(xy.values(1)) - 2.9) < 1e-9;
  }
  EXPECT_TRUE(found_corner);
  const auto& area_properties = corridor.fields().at("properties").struct_value().fields();
  EXPECT_EQ(Number(area_properties.at("area_id")), 1);
  EXPECT_EQ(area_properties.at("kind").string_value(), "corridor");
  EXPECT_DOUBLE_EQ(Number(area_properties.at("area_m2")), 0.24);

  const Struct& passage = features.values(2).struct_value();
  EXPECT_EQ(passage.fields().at("id").string_value(), "passage/0");
  const Struct& line = passage.fields().at("geometry").struct_value();
  EXPECT_EQ(line.fields().at("type").string_value(), "LineString");
  // The passage is the border the two areas share, all three of its points.
  const auto& coordinates = line.fields().at("coordinates").list_value();
  ASSERT_EQ(coordinates.values_size(), 3);
  EXPECT_NEAR(Number(coordinates.values(1).list_value().values(1)), 2.0 + (20 - 7) * 0.05, 1e-9);
  const auto& passage_properties = passage.fields().at("properties").struct_value().fields();
  EXPECT_EQ(passage_properties.at("kind").string_value(), "passage");
  EXPECT_DOUBLE_EQ(Number(passage_properties.at("width_m")), 0.3);
  EXPECT_EQ(Number(passage_properties.at("from")), 0);
  EXPECT_EQ(Number(passage_properties.at("to")), 1);
}

TEST_F(AgExportCli, GeoJsonWithAnAnchorIsWgs84) {
  const auto run =
      Export("geojson", dir_.File("map.geojson"),
             {"--anchor-lat", "48.1", "--anchor-lon", "11.5", "--features", "passages"});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const Struct collection = ReadJson(dir_.File("map.geojson"));
  EXPECT_EQ(collection.fields().at("units").string_value(), "degrees");
  EXPECT_EQ(collection.fields().count("crs"), 0u);
  const auto& features = collection.fields().at("features").list_value();
  ASSERT_EQ(features.values_size(), 1);  // the passage only
  const auto& first = features.values(0)
                          .struct_value()
                          .fields()
                          .at("geometry")
                          .struct_value()
                          .fields()
                          .at("coordinates")
                          .list_value()
                          .values(0)
                          .list_value();
  // Border point (12, 4) px is world (1.6, 2.8) m: [lon, lat] as RFC 7946 orders them.
  // Degrees to 8 decimals (about a millimetre), with no float noise.
  const LatLon expected = MetresToLatLon({48.1, 11.5}, 1.6, 2.8);
  EXPECT_EQ(Number(first.values(0)), std::round(expected.lon_deg * 1e8) / 1e8);
  EXPECT_EQ(Number(first.values(1)), std::round(expected.lat_deg * 1e8) / 1e8);
  const std::string text = ReadFile(dir_.File("map.geojson"));
  EXPECT_NE(text.find("[11.50002152,48.10002515]"), std::string::npos) << text;
}

// The <way> blocks of an OSM file, in order.
std::vector<std::string> WayBlocks(const std::string& xml) {
  std::vector<std::string> ways;
  const std::regex way("<way [^>]*>[\\s\\S]*?</way>");
  for (auto it = std::sregex_iterator(xml.begin(), xml.end(), way); it != std::sregex_iterator();
       ++it) {
    ways.push_back(it->str());
  }
  return ways;
}

std::vector<std::string> NodeRefs(const std::string& way) {
  std::vector<std::string> refs;
  const std::regex nd("<nd ref=\"(-\\d+)\"/>");
  for (auto it = std::sregex_iterator(way.begin(), way.end(), nd); it != std::sregex_iterator();
       ++it) {
    refs.push_back((*it)[1]);
  }
  return refs;
}

bool HasTag(const std::string& block, const std::string& key, const std::string& value) {
  return block.find("<tag k=\"" + key + "\" v=\"" + value + "\"/>") != std::string::npos;
}

TEST_F(AgExportCli, OsmAgHasAreasThenPassagesWithTheirTags) {
  const auto run =
      RunTool("ag-export", {"--store", store_path_, "--map", "house", "--format", "osmag", "--out",
                            dir_.File("map.osm"), "--anchor-lat", "48.1", "--anchor-lon", "11.5"});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const std::string xml = ReadFile(dir_.File("map.osm"));
  EXPECT_NE(xml.find("<osm version=\"0.6\" generator=\"areagraph\" upload=\"never\">"),
            std::string::npos);
  EXPECT_NE(xml.find("lat=\"48.1000000\" lon=\"11.5000000\">"), std::string::npos);
  EXPECT_NE(xml.find("<tag k=\"osmAG:map\" v=\"house\"/>"), std::string::npos);
  EXPECT_LT(xml.rfind("<node "), xml.find("<way "));

  // The structure, the room, the corridor's outer ring and hole (untagged:
  // its relation is the area), the passage; then the corridor's relation.
  const std::vector<std::string> ways = WayBlocks(xml);
  ASSERT_EQ(ways.size(), 5u);
  EXPECT_TRUE(HasTag(ways[0], "osmAG:areaType", "structure"));
  EXPECT_TRUE(HasTag(ways[0], "name", "house"));
  const size_t relation_at = xml.find("<relation ");
  ASSERT_NE(relation_at, std::string::npos);
  EXPECT_LT(xml.rfind("<way "), relation_at);
  const std::string relation = xml.substr(relation_at);
  EXPECT_TRUE(HasTag(relation, "type", "multipolygon"));
  const std::vector<std::string> areas = {ways[1], relation};
  for (size_t i = 0; i < areas.size(); ++i) {
    EXPECT_TRUE(HasTag(areas[i], "osmAG:type", "area"));
    EXPECT_TRUE(HasTag(areas[i], "osmAG:areaType", "room"));
    EXPECT_TRUE(HasTag(areas[i], "osmAG:parent", "house"));
    EXPECT_TRUE(HasTag(areas[i], "name", "area_" + std::to_string(i)));
  }
  EXPECT_TRUE(HasTag(ways[1], "areagraph:kind", "room"));
  EXPECT_TRUE(HasTag(relation, "areagraph:kind", "corridor"));
  EXPECT_EQ(ways[2].find("<tag "), std::string::npos);
  EXPECT_EQ(ways[3].find("<tag "), std::string::npos);
  for (int i = 1; i < 3; ++i) {
    const std::vector<std::string> refs = NodeRefs(ways[i]);
    ASSERT_EQ(refs.size(), 8u);            // 4 corners, 3 border points, the closing repeat
    EXPECT_EQ(refs.front(), refs.back());  // closed
  }
  const std::vector<std::string> passage = NodeRefs(ways[4]);
  EXPECT_EQ(passage.size(), 3u);
  EXPECT_TRUE(HasTag(ways[4], "osmAG:type", "passage"));
  EXPECT_TRUE(HasTag(ways[4], "areagraph:width", "0.300"));
  EXPECT_TRUE(HasTag(ways[4], "osmAG:from", "area_0"));
  EXPECT_TRUE(HasTag(ways[4], "osmAG:to", "area_1"));
  // The two squares share their common edge's two corners and the passage's
  // three nodes.
  std::vector<std::string> room = NodeRefs(ways[1]), corridor = NodeRefs(ways[2]);
  room.pop_back();  // the closing repeat
  corridor.pop_back();
  int shared = 0;
  for (const std::string& ref : room) {
    shared += static_cast<int>(std::count(corridor.begin(), corridor.end(), ref));
  }
  EXPECT_EQ(shared, 5);
  for (const std::string& ref : passage) {
    EXPECT_EQ(std::count(room.begin(), room.end(), ref), 1);
    EXPECT_EQ(std::count(corridor.begin(), corridor.end(), ref), 1);
  }
}

TEST_F(AgExportCli, ProtoJsonReadsBackAsTheSameAreaGraph) {
  const auto run = Export("protojson", dir_.File("map.json"));
  ASSERT_EQ(run.exit_code, 0) << run.err;
  proto::AreaGraph parsed;
  ASSERT_TRUE(
      google::protobuf::util::JsonStringToMessage(ReadFile(dir_.File("map.json")), &parsed).ok());
  EXPECT_TRUE(
      google::protobuf::util::MessageDifferencer::Equals(parsed, testing::TwoRoomAreaGraph()));
}

TEST_F(AgExportCli, JsonIsNodeLinkWithKindNamesAsInGeoJson) {
  const auto run = Export("json", dir_.File("graph.json"));
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const Struct graph = ReadJson(dir_.File("graph.json"));
  EXPECT_FALSE(graph.fields().at("directed").bool_value());
  EXPECT_TRUE(graph.fields().at("multigraph").bool_value());
  EXPECT_EQ(graph.fields().at("graph").struct_value().fields().at("name").string_value(), "house");
  const auto& nodes = graph.fields().at("nodes").list_value();
  ASSERT_EQ(nodes.values_size(), 2);
  EXPECT_EQ(nodes.values(1).struct_value().fields().at("kind").string_value(), "corridor");
  const auto& polygon = nodes.values(0).struct_value().fields().at("polygon").list_value();
  ASSERT_EQ(polygon.values_size(), 4);
  EXPECT_NEAR(Number(polygon.values(0).list_value().values(0)), 1.1, 1e-9);
  for (const char* links : {"links", "edges"}) {
    const auto& list = graph.fields().at(links).list_value();
    ASSERT_EQ(list.values_size(), 1);
    const auto& link = list.values(0).struct_value().fields();
    EXPECT_EQ(Number(link.at("source")), 0);
    EXPECT_EQ(Number(link.at("target")), 1);
    EXPECT_EQ(Number(link.at("key")), 0);
    EXPECT_EQ(link.at("border").list_value().values_size(), 3);
  }
}

TEST_F(AgExportCli, OptionsOfAnotherFormatAreOneLineErrors) {
  for (const std::vector<std::string>& extra :
       {std::vector<std::string>{"--format", "osmag", "--features", "areas"},
        {"--format", "geojson", "--level", "1"},
        {"--format", "geojson", "--anchor-lat", "40"},
        {"--format", "json", "--anchor-lat", "40", "--anchor-lon", "8"},
        {"--format", "geojson", "--features", "doors"}}) {
    std::vector<std::string> args = {"--store", store_path_, "--map",
                                     "house",   "--out",     dir_.File("x")};
    args.insert(args.end(), extra.begin(), extra.end());
    const auto run = RunTool("ag-export", args);
    EXPECT_EQ(run.exit_code, 2) << extra[2];
    EXPECT_EQ(CountLines(run.err), 1) << run.err;
  }
}

TEST_F(AgExportCli, UnknownFormatIsOneLineAndNonZero) {
  const auto run = Export("pdf", dir_.File("map.pdf"));
  EXPECT_NE(run.exit_code, 0);
  EXPECT_EQ(CountLines(run.err), 1) << run.err;
  EXPECT_NE(run.err.find("pdf"), std::string::npos) << run.err;
}

TEST_F(AgExportCli, UnwritableOutputIsOneLineAndNonZero) {
  const auto run = Export("geojson", dir_.File("no/such/folder/map.geojson"));
  EXPECT_NE(run.exit_code, 0);
  EXPECT_EQ(run.signal, 0);
  EXPECT_EQ(CountLines(run.err), 1) << run.err;
  EXPECT_NE(run.err.find("map.geojson"), std::string::npos) << run.err;
}

TEST_F(AgExportCli, MissingMergeArtifactNamesTheStageToRun) {
  {
    std::unique_ptr<ArtifactStore> store = OpenArtifactStore(store_path_);
    StageInputs inputs;
    inputs.digests = {"source"};
    RunCachedStage(*store, "other", StageOf(kImportStage), {}, inputs,
                   [] { return std::make_unique<proto::GridMap>(); });
  }
  auto run = RunTool("ag-export", {"--store", store_path_, "--map", "other", "--format", "json",
                                   "--out", dir_.File("other.json")});
  EXPECT_NE(run.exit_code, 0);
  EXPECT_EQ(CountLines(run.err), 1) << run.err;
  EXPECT_NE(run.err.find("ag-merge"), std::string::npos) << run.err;
  run = RunTool("ag-export", {"--store", store_path_, "--map", "nowhere", "--format", "json",
                              "--out", dir_.File("nowhere.json")});
  EXPECT_NE(run.exit_code, 0);
  EXPECT_NE(run.err.find("nowhere"), std::string::npos) << run.err;
}

// --all writes each map's file into the folder under the map's name (folders
// of a name included), byte for byte what --map writes; a map without an Area
// Graph is named on one line of stderr and makes the status 1.
TEST_F(AgExportCli, AllWritesEveryMapIntoTheFolder) {
  {
    std::unique_ptr<ArtifactStore> store = OpenArtifactStore(store_path_);
    StageInputs inputs;
    inputs.digests = {"cut-artifact-digest"};
    RunCachedStage(*store, "wing/floor_2", StageOf(kMergeStage), {}, inputs,
                   [] { return std::make_unique<proto::AreaGraph>(testing::TwoRoomAreaGraph()); });
  }
  ASSERT_EQ(Export("kinds", dir_.File("house.kinds.tsv")).exit_code, 0);
  auto run = RunTool("ag-export", {"--store", store_path_, "--all", "--format", "kinds", "--out",
                                   dir_.File("all")});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_EQ(ReadFile(dir_.File("all/house.kinds.tsv")), ReadFile(dir_.File("house.kinds.tsv")));
  EXPECT_EQ(ReadFile(dir_.File("all/wing/floor_2.kinds.tsv")),
            ReadFile(dir_.File("house.kinds.tsv")));
  EXPECT_EQ(CountLines(run.out), 2) << run.out;

  {
    std::unique_ptr<ArtifactStore> store = OpenArtifactStore(store_path_);
    StageInputs inputs;
    inputs.digests = {"source"};
    RunCachedStage(*store, "imported_only", StageOf(kImportStage), {}, inputs,
                   [] { return std::make_unique<proto::GridMap>(); });
  }
  run = RunTool("ag-export", {"--store", store_path_, "--all", "--format", "labels", "--out",
                              dir_.File("labels")});
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_EQ(CountLines(run.err), 1) << run.err;
  EXPECT_NE(run.err.find("1 of 3 maps have no Area Graph"), std::string::npos) << run.err;
  EXPECT_NE(run.err.find("imported_only"), std::string::npos) << run.err;
  EXPECT_TRUE(cv::imread(dir_.File("labels/house.png"), cv::IMREAD_UNCHANGED).type() == CV_16U);

  for (const std::vector<std::string>& wrong :
       {std::vector<std::string>{"--all", "--map", "house", "--format", "json", "--out", "x"},
        {"--format", "json", "--out", "x"},
        {"--all", "--format", "html", "--out", "x"},
        {"--all", "--format", "json", "--out", "-"}}) {
    std::vector<std::string> args = {"--store", store_path_};
    args.insert(args.end(), wrong.begin(), wrong.end());
    run = RunTool("ag-export", args);
    EXPECT_EQ(run.exit_code, 2) << wrong[1];
    EXPECT_EQ(CountLines(run.err), 1) << run.err;
  }
}

}  // namespace
}  // namespace areagraph

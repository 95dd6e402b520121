// ag-export's files opened with the tools their users already run (all from
// Debian, see tools/install-deps.sh): the osmAG rules checked by parsing the
// XML, GeoJSON through GDAL's ogr2ogr and shapely, node-link JSON through
// networkx, the preview PNG through OpenCV. On a real map with parallel
// passages: freiburg_building79 from ../shared/data.
#include <gtest/gtest.h>

#include <memory>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "proto/artifacts.pb.h"
#include "stages/pipeline/stage.h"
#include "store/artifact_store.h"
#include "tests/support/test_support.h"

namespace areagraph::testing {
namespace {

constexpr char kMap[] = "freiburg_building79";
// Debian's interpreter, which has python3-shapely and python3-networkx.
constexpr char kPython[] = "/usr/bin/python3";

class ExportEcosystem : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    if (!HaveSharedData()) return;
    dir_ = new TempDir();
    const CommandResult run =
        RunTool("ag-run", {"--store", Store(), "--jobs", "1",
                           SharedDataPath(std::string("areagraph/input/") + kMap + ".png")});
    ASSERT_EQ(run.exit_code, 0) << run.err;
    std::unique_ptr<ArtifactStore> store = OpenArtifactStore(Store(), StoreMode::kReadOnly);
    graph_ = new proto::AreaGraph(ReadHeadArtifact<proto::AreaGraph>(*store, kMap, kMergeStage));
  }
  static void TearDownTestSuite() {
    delete graph_;
    delete dir_;
  }
  void SetUp() override {
    if (!HaveSharedData()) GTEST_SKIP() << "../shared/data is missing";
  }

  static std::string Store() { return dir_->File("store.db"); }
  static std::string File(const std::string& name) { return dir_->File(name); }

  // ag-export of the map to `out` in `format`, with `extra` options.
  static void Export(const std::string& format, const std::string& out,
                     std::vector<std::string> extra = {}) {
    std::vector<std::string> args = {"--store",  Store(), "--map", kMap,
                                     "--format", format,  "--out", out};
    args.insert(args.end(), extra.begin(), extra.end());
    const CommandResult run = RunTool("ag-export", args);
    ASSERT_EQ(run.exit_code, 0) << run.err;
  }

  static CommandResult Check(const std::string& script, std::vector<std::string> args) {
    args.insert(args.begin(), {kPython, SourcePath("tests/tools/export/python/" + script)});
    return RunProgram(args);
  }

  static TempDir* dir_;
  static proto::AreaGraph* graph_;
};

TempDir* ExportEcosystem::dir_ = nullptr;
proto::AreaGraph* ExportEcosystem::graph_ = nullptr;

TEST_F(ExportEcosystem, OsmAgFollowsTheSpec) {
  Export("osmag", File("map.osm"),
         {"--level", "2", "--height", "2.8", "--anchor-lat", "48", "--anchor-lon", "7.8"});
  const CommandResult check = Check(
      "check_osmag.py",
      {File("map.osm"), "--map", kMap, "--level", "2", "--height", "2.8", "--anchor", "48", "7.8"});
  ASSERT_EQ(check.exit_code, 0) << check.err;
  int border_points = 0;
  for (const proto::Passage& passage : graph_->passages()) {
    border_points += passage.border_m_size();
  }
  EXPECT_EQ(check.out, std::to_string(graph_->areas_size()) + " areas, " +
                           std::to_string(graph_->passages_size()) + " passages, " +
                           std::to_string(border_points) + " passage nodes shared\n");

  // The checker fails on a passage tagged as a door (which JOSM reads as a
  // door node on a way), and on the wrong level.
  std::string xml = ReadFile(File("map.osm"));
  const std::string passage_tag = "<tag k=\"osmAG:type\" v=\"passage\"/>";
  xml.insert(xml.find(passage_tag), "<tag k=\"indoor\" v=\"door\"/>");
  WriteFile(File("broken.osm"), xml);
  EXPECT_EQ(Check("check_osmag.py",
                  {File("broken.osm"), "--map", kMap, "--level", "2", "--height", "2.8"})
                .exit_code,
            1);
  EXPECT_EQ(
      Check("check_osmag.py", {File("map.osm"), "--map", kMap, "--level", "0", "--height", "2.8"})
          .exit_code,
      1);
}

TEST_F(ExportEcosystem, GeoJsonOpensInGdalAndShapely) {
  const std::string expected = std::to_string(graph_->areas_size()) + " areas, " +
                               std::to_string(graph_->passages_size()) +
                               " passages, all polygons valid\n";
  Export("geojson", File("local.geojson"));
  CommandResult check = Check("check_geojson.py", {File("local.geojson"), "--map", kMap});
  ASSERT_EQ(check.exit_code, 0) << check.err;
  EXPECT_EQ(check.out, expected);
  Export("geojson", File("wgs84.geojson"), {"--anchor-lat", "48", "--anchor-lon", "7.8"});
  check =
      Check("check_geojson.py", {File("wgs84.geojson"), "--map", kMap, "--anchor", "48", "7.8"});
  ASSERT_EQ(check.exit_code, 0) << check.err;
  EXPECT_EQ(check.out, expected);

  for (const std::string name : {"local", "wgs84"}) {
    const CommandResult gpkg = RunProgram(
        {"/usr/bin/ogr2ogr", "-f", "GPKG", File(name + ".gpkg"), File(name + ".geojson")});
    EXPECT_EQ(gpkg.exit_code, 0) << gpkg.err;
    const CommandResult info = RunProgram({"/usr/bin/ogrinfo", "-so", File(name + ".gpkg"), kMap});
    EXPECT_NE(info.out.find("Feature Count: " +
                            std::to_string(graph_->areas_size() + graph_->passages_size())),
              std::string::npos)
        << info.out;
    // Metres are a local engineering CRS, not degrees.
    EXPECT_NE(info.out.find(name == "local" ? "ENGCRS[\"areagraph map frame\"" : "WGS 84"),
              std::string::npos)
        << info.out;
  }
  for (const std::string features : {"areas", "passages"}) {
    Export("geojson", File(features + ".geojson"), {"--features", features});
    const CommandResult shapefile =
        RunProgram({"/usr/bin/ogr2ogr", "-f", "ESRI Shapefile", File(features + "_shp"),
                    File(features + ".geojson")});
    EXPECT_EQ(shapefile.exit_code, 0) << shapefile.err;
  }
}

TEST_F(ExportEcosystem, NodeLinkJsonLoadsInNetworkxWithParallelPassages) {
  Export("json", File("graph.json"));
  const CommandResult check = Check("check_node_link.py", {File("graph.json")});
  ASSERT_EQ(check.exit_code, 0) << check.err;
  std::set<std::pair<int, int>> pairs;
  std::set<std::string> kinds;
  for (const proto::Passage& passage : graph_->passages()) {
    pairs.insert(std::minmax(passage.area_a(), passage.area_b()));
  }
  // The map has passages in parallel, which a plain nx.Graph would merge.
  ASSERT_LT(pairs.size(), static_cast<size_t>(graph_->passages_size()));
  EXPECT_EQ(
      check.out.rfind(std::string(kMap) + ": MultiGraph, " + std::to_string(graph_->areas_size()) +
                          " nodes, " + std::to_string(graph_->passages_size()) + " edges, " +
                          std::to_string(pairs.size()) + " area pairs, kinds ",
                      0),
      0u)
      << check.out;
}

TEST_F(ExportEcosystem, PreviewIsAColourPngWithRedPassages) {
  Export("preview", File("preview.png"));
  const cv::Mat preview = cv::imread(File("preview.png"), cv::IMREAD_UNCHANGED);
  ASSERT_EQ(preview.type(), CV_8UC3);
  EXPECT_EQ(preview.cols % graph_->frame().width_px(), 0);
  EXPECT_EQ(preview.rows / graph_->frame().height_px(), preview.cols / graph_->frame().width_px());
  std::set<int> colours;
  int red = 0;
  for (int r = 0; r < preview.rows; ++r) {
    for (int c = 0; c < preview.cols; ++c) {
      const cv::Vec3b bgr = preview.at<cv::Vec3b>(r, c);
      colours.insert(bgr[0] << 16 | bgr[1] << 8 | bgr[2]);
      red += bgr == cv::Vec3b(0, 0, 220);
    }
  }
  EXPECT_GT(colours.size(), static_cast<size_t>(graph_->areas_size()));
  EXPECT_GT(red, graph_->passages_size());
}

}  // namespace
}  // namespace areagraph::testing

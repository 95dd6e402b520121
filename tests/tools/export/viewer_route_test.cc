// Routes in the HTML viewer: the route graph the page embeds is the C++
// router's, and in headless chromium two clicks draw a route as long as
// ag-route's between the same points.
#include <google/protobuf/struct.pb.h>
#include <google/protobuf/util/json_util.h>
#include <gtest/gtest.h>

#include <memory>
#include <regex>
#include <string>

#include "stages/common/map_frame.h"
#include "stages/pipeline/stage.h"
#include "store/artifact_store.h"
#include "tests/support/headless_chromium.h"
#include "tests/support/test_support.h"
#include "tools/export/viewer_route_layer.h"
#include "tools/route/area_router.h"

namespace areagraph {
namespace {

using testing::FileUrl;
using testing::HeadlessChromium;
using testing::RunTool;
using testing::TempDir;

class ViewerRoutes : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto run = RunTool("ag-run", {"--store", store_, "--jobs", "1",
                                        testing::SourcePath("examples/office_small.png")});
    ASSERT_EQ(run.exit_code, 0) << run.err;
    std::unique_ptr<ArtifactStore> store = OpenArtifactStore(store_, StoreMode::kReadOnly);
    graph_ = ReadHeadArtifact<proto::AreaGraph>(*store, "office_small", kMatchStage);
  }

  TempDir dir_;
  const std::string store_ = dir_.File("areagraph.db");
  proto::AreaGraph graph_;
};

TEST_F(ViewerRoutes, PageHoldsTheRoutersGraphInPixels) {
  viewer::Run run;
  SetRouteGraph(graph_, &run);
  ASSERT_TRUE(run.has_route_graph());
  const viewer::RouteGraph& page = run.route_graph();
  const AreaRouter router(graph_);
  ASSERT_EQ(page.corners_size(), 2 * router.corner_count());
  ASSERT_EQ(page.corner_kinds_size(), router.corner_count());
  ASSERT_EQ(page.corner_walls_size(), 4 * router.corner_count());
  EXPECT_EQ(page.links_size(), 2 * router.link_count());
  ASSERT_EQ(page.areas_size(), graph_.areas_size());
  const MapTransform transform(graph_.frame());
  for (int c = 0; c < router.corner_count(); ++c) {
    const Eigen::Vector2d pixel = transform.WorldToPixel(router.corner(c).at);
    EXPECT_NEAR(page.corners(2 * c), pixel.x(), 0.005);
    EXPECT_NEAR(page.corners(2 * c + 1), pixel.y(), 0.005);
  }
  int walls = 0;
  for (const OutlineEdge& edge : router.free_space().edges()) walls += edge.wall;
  EXPECT_GT(page.walls_size() / 4, walls / 2 - 1) << "each wall at most twice";
  EXPECT_LE(page.walls_size() / 4, walls);

  proto::AreaGraph without_metres = graph_;
  for (proto::Area& area : *without_metres.mutable_areas()) area.clear_polygon_m();
  SetRouteGraph(without_metres, &run);
  EXPECT_FALSE(run.has_route_graph());
}

// Clicks "Plan a route" and then two map pixels (START_X, ...), and leaves
// the route's length and the status line on <body data-probe>.
constexpr char kRouteProbe[] = R"(<script>
(function () {
  const svg = document.querySelector('.view svg');
  const viewport = svg.querySelector('g.viewport');
  const k = Number(/scale\(([^)]*)\)/.exec(viewport.getAttribute('transform'))[1]);
  const [tx, ty] = /translate\(([^ ]*) ([^)]*)\)/.exec(viewport.getAttribute('transform')).slice(1).map(Number);
  const box = svg.getBoundingClientRect();
  const at = (x, y) => ({ clientX: box.left + tx + k * x, clientY: box.top + ty + k * y, bubbles: true, cancelable: true, button: 0, pointerId: 1 });
  document.getElementById('route-button').click();
  for (const [x, y] of [[START_X, START_Y], [GOAL_X, GOAL_Y]]) {
    svg.dispatchEvent(new PointerEvent('pointerdown', at(x, y)));
    svg.dispatchEvent(new PointerEvent('pointerup', at(x, y)));
  }
  const route = svg.querySelector('g.route');
  document.body.dataset.probe = JSON.stringify({
    length: route ? Number(route.dataset.lengthM) : -1,
    points: route && route.querySelector('polyline') ? route.querySelector('polyline').getAttribute('points') : '',
    status: document.getElementById('route-status').textContent,
    hash: location.hash,
  });
})();
</script>)";

TEST_F(ViewerRoutes, TwoClicksDrawTheRouteThatAgRouteFinds) {
  if (!HeadlessChromium::NotInstalled().empty()) GTEST_SKIP() << HeadlessChromium::NotInstalled();
  const std::string page_path = dir_.File("office_small.html");
  const auto page = RunTool("ag-export", {"--store", store_, "--map", "office_small", "--format",
                                          "html", "--out", page_path});
  ASSERT_EQ(page.exit_code, 0) << page.err;
  // Two points inside areas far apart: the centroids of the first and the
  // last area that hold their own centroid.
  const AreaRouter router(graph_);
  std::vector<Vec2> inside;
  for (const proto::Area& area : graph_.areas()) {
    const Vec2 centroid(area.centroid_m().x(), area.centroid_m().y());
    if (router.free_space().AreaAt(centroid) == area.id()) inside.push_back(centroid);
  }
  ASSERT_GE(inside.size(), 2u);
  const Vec2 start = inside.front(), goal = inside.back();
  const RouteAnswer expected = router.FindRoute(start, goal);
  ASSERT_TRUE(expected.route) << expected.no_route_reason;
  const MapTransform transform(graph_.frame());
  std::string probe = kRouteProbe;
  const Eigen::Vector2d start_px = transform.WorldToPixel(start);
  const Eigen::Vector2d goal_px = transform.WorldToPixel(goal);
  for (const auto& [name, value] : {std::pair{"START_X", start_px.x()},
                                    {"START_Y", start_px.y()},
                                    {"GOAL_X", goal_px.x()},
                                    {"GOAL_Y", goal_px.y()}}) {
    probe = std::regex_replace(probe, std::regex(name), std::to_string(value));
  }
  std::string html = testing::ReadFile(page_path);
  html.insert(html.rfind("</body>"), probe);
  testing::WriteFile(dir_.File("probe.html"), html);
  const auto load = HeadlessChromium::DumpDom(FileUrl(dir_.File("probe.html")));
  if (load.exit_code != 0 && !HeadlessChromium::Unavailable().empty()) {
    GTEST_SKIP() << HeadlessChromium::Unavailable();
  }
  EXPECT_EQ(load.dom.find("data-errors="), std::string::npos) << load.dom.substr(0, 400);
  std::smatch match;
  ASSERT_TRUE(std::regex_search(load.dom, match, std::regex("data-probe=\"([^\"]*)\"")));
  google::protobuf::Struct result;
  const std::string json = std::regex_replace(match[1].str(), std::regex("&quot;"), "\"");
  ASSERT_TRUE(google::protobuf::util::JsonStringToMessage(json, &result).ok()) << json;
  const auto& fields = result.fields();
  // The page sees walls a little more strictly and rounds to 0.01 px.
  const double length = fields.at("length").number_value();
  EXPECT_GE(length, expected.route->length_m - 0.002);
  EXPECT_LE(length, expected.route->length_m * 1.02 + 0.002);
  EXPECT_NE(fields.at("status").string_value().find("Route: "), std::string::npos)
      << fields.at("status").string_value();
  EXPECT_FALSE(fields.at("points").string_value().empty());
  EXPECT_EQ(fields.at("hash").string_value().find("select="), std::string::npos)
      << "a planning click does not select";
}

}  // namespace
}  // namespace areagraph

// The HTML viewer (ag-export --format html) in a real browser: Debian's
// chromium, headless, on the page of the shipped example office_small. The
// tests skip only where chromium cannot start.
#include <google/protobuf/struct.pb.h>
#include <google/protobuf/util/json_util.h>
#include <gtest/gtest.h>

#include <memory>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <regex>
#include <string>

#include "proto/artifacts.pb.h"
#include "stages/pipeline/stage.h"
#include "store/artifact_store.h"
#include "tests/support/headless_chromium.h"
#include "tests/support/test_support.h"

namespace areagraph {
namespace {

using testing::CountOccurrences;
using testing::FileUrl;
using testing::HeadlessChromium;
using testing::ReadFile;
using testing::RunTool;
using testing::TempDir;

// One store with two runs of office_small (a smaller W and minimum area for
// the diff view, then the default options, which stay the heads) and the
// pages exported from it, made once for all tests.
struct ExampleStore {
  TempDir dir;
  std::string store = dir.File("areagraph.db");
  std::string page = dir.File("office_small.html");
  std::string diff_page = dir.File("diff.html");
  std::string other_merge_key;
  proto::AreaGraph graph;
};

class ViewerInBrowser : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    example_ = new ExampleStore();
    const std::string map = testing::SourcePath("examples/office_small.png");
    const auto other = RunTool("ag-run", {"--store", example_->store, "--jobs", "1", "--set",
                                          "cut.room_width_m=0.9", "--set", "merge.min_area_m2=2",
                                          "--set", "cut.skip_passes=CLOSE_WALL_GAPS", map});
    ASSERT_EQ(other.exit_code, 0) << other.err;
    const auto heads = RunTool("ag-run", {"--store", example_->store, "--jobs", "1", map});
    ASSERT_EQ(heads.exit_code, 0) << heads.err;
    std::unique_ptr<ArtifactStore> store = OpenArtifactStore(example_->store);
    for (const ArtifactRecord& artifact : store->ReadArtifactSummaries("office_small")) {
      if (artifact.stage == "merge" && !artifact.is_head) {
        example_->other_merge_key = artifact.cache_key;
      }
    }
    // The published graph, which the viewer shows: stable ids as labels.
    example_->graph = ReadHeadArtifact<proto::AreaGraph>(*store, "office_small", kMatchStage);
    const auto page = RunTool("ag-export", {"--store", example_->store, "--map", "office_small",
                                            "--format", "html", "--out", example_->page});
    ASSERT_EQ(page.exit_code, 0) << page.err;
    const auto diff =
        RunTool("ag-export", {"--store", example_->store, "--map", "office_small", "--format",
                              "html", "--compare", example_->other_merge_key.substr(0, 10), "--out",
                              example_->diff_page});
    ASSERT_EQ(diff.exit_code, 0) << diff.err;
  }

  static void TearDownTestSuite() {
    delete example_;
    example_ = nullptr;
  }

  void SetUp() override {
    if (!HeadlessChromium::NotInstalled().empty()) GTEST_SKIP() << HeadlessChromium::NotInstalled();
  }

  static ExampleStore* example_;
};

ExampleStore* ViewerInBrowser::example_ = nullptr;

// After a failed browser run: skip when chromium cannot start here at all,
// else let the test fail.
#define SKIP_UNLESS_BROWSER_RAN(ran)                        \
  if (!(ran) && !HeadlessChromium::Unavailable().empty()) { \
    GTEST_SKIP() << HeadlessChromium::Unavailable();        \
  }

// The text content of the element with this id (tags stripped).
std::string ElementText(const std::string& dom, const std::string& id) {
  const size_t start = dom.find("id=\"" + id + "\"");
  if (start == std::string::npos) return "";
  const size_t end = dom.find("</section>", start);
  const std::string inner = dom.substr(start, end - start);
  return std::regex_replace(inner, std::regex("<[^>]*>"), " ");
}

TEST_F(ViewerInBrowser, DomHasOneElementPerAreaAndPassage) {
  ASSERT_GT(example_->graph.areas_size(), 3);
  ASSERT_GT(example_->graph.passages_size(), 0);
  const auto load = HeadlessChromium::DumpDom(FileUrl(example_->page));
  SKIP_UNLESS_BROWSER_RAN(load.exit_code == 0);
  ASSERT_EQ(load.exit_code, 0);
  EXPECT_NE(load.dom.find("data-ready="), std::string::npos) << "the script did not finish";
  EXPECT_EQ(CountOccurrences(load.dom, "class=\"area\""), example_->graph.areas_size());
  EXPECT_EQ(CountOccurrences(load.dom, "class=\"passage\""), example_->graph.passages_size());
  for (const proto::Area& area : example_->graph.areas()) {
    EXPECT_NE(load.dom.find("data-sel=\"area/" + std::to_string(area.id()) + "\""),
              std::string::npos);
  }
}

// Fraction of pixels that differ between two screenshots of the same size.
double DifferingFraction(const cv::Mat& a, const cv::Mat& b) {
  cv::Mat difference;
  cv::absdiff(a, b, difference);
  cv::cvtColor(difference, difference, cv::COLOR_BGR2GRAY);
  return static_cast<double>(cv::countNonZero(difference > 8)) / (a.rows * a.cols);
}

TEST_F(ViewerInBrowser, ScreenshotIsNotBlankAndFollowsTheLayersInTheFragment) {
  const std::string areas_png = example_->dir.File("areas.png"),
                    voronoi_png = example_->dir.File("voronoi.png");
  const bool ran = HeadlessChromium::Screenshot(FileUrl(example_->page), areas_png, 1000, 700);
  SKIP_UNLESS_BROWSER_RAN(ran);
  ASSERT_TRUE(ran);
  ASSERT_TRUE(HeadlessChromium::Screenshot(FileUrl(example_->page) + "#layers=voronoi", voronoi_png,
                                           1000, 700));
  const cv::Mat areas = cv::imread(areas_png, cv::IMREAD_COLOR);
  const cv::Mat voronoi = cv::imread(voronoi_png, cv::IMREAD_COLOR);
  ASSERT_FALSE(areas.empty());
  ASSERT_EQ(areas.size(), voronoi.size());
  // Not blank: the map side of the picture holds many colours.
  cv::Scalar mean, deviation;
  cv::meanStdDev(areas(cv::Rect(0, 0, areas.cols * 2 / 3, areas.rows)), mean, deviation);
  EXPECT_GT(deviation[0] + deviation[1] + deviation[2], 30);
  // The layer switch changes a large part of the map.
  EXPECT_GT(DifferingFraction(areas, voronoi), 0.05);
}

TEST_F(ViewerInBrowser, SelectInTheFragmentShowsTheAreaInThePanel) {
  ASSERT_GT(example_->graph.areas_size(), 3);
  const int stable_id = example_->graph.areas(3).stable_id();
  const auto load = HeadlessChromium::DumpDom(FileUrl(example_->page) + "#select=area/3");
  SKIP_UNLESS_BROWSER_RAN(load.exit_code == 0);
  ASSERT_EQ(load.exit_code, 0);
  EXPECT_NE(load.dom.find("data-selected=\"area/3\""), std::string::npos);
  const std::string info = ElementText(load.dom, "info");
  // Titled by its stable id; its index in this version is given too.
  EXPECT_NE(info.find("Area " + std::to_string(stable_id) + " "), std::string::npos) << info;
  EXPECT_NE(info.find("index in this version  3"), std::string::npos) << info;
  EXPECT_NE(info.find("m²"), std::string::npos) << info;
  // The selected area is outlined on the map.
  EXPECT_TRUE(
      std::regex_search(load.dom, std::regex("class=\"area selected\"[^>]*data-sel=\"area/3\"")));
}

// The panel names the areas a passage joins by their stable ids too, as the
// map's labels do, not by their indices in this version.
TEST_F(ViewerInBrowser, PanelNamesNeighboursByStableId) {
  const proto::AreaGraph& graph = example_->graph;
  const proto::Passage* chosen = nullptr;
  for (const proto::Passage& passage : graph.passages()) {
    if (graph.areas(passage.area_b()).stable_id() != passage.area_b()) chosen = &passage;
  }
  ASSERT_NE(chosen, nullptr) << "every neighbour's stable id equals its index";
  const int other = graph.areas(chosen->area_b()).stable_id();
  const auto load = HeadlessChromium::DumpDom(FileUrl(example_->page) + "#select=area/" +
                                              std::to_string(chosen->area_a()));
  SKIP_UNLESS_BROWSER_RAN(load.exit_code == 0);
  ASSERT_EQ(load.exit_code, 0);
  const std::string info = ElementText(load.dom, "info");
  EXPECT_NE(info.find("to area " + std::to_string(other) + ")"), std::string::npos) << info;
  EXPECT_NE(info.find(" " + std::to_string(chosen->stable_id()) + " "), std::string::npos) << info;
}

// Whether a page load shows any sign of a request or a script error: a
// console message (chromium logs blocked requests there) or an error that
// the page recorded itself.
std::string TroubleOf(const HeadlessChromium::PageLoad& load) {
  std::string trouble = load.console;
  std::smatch errors;
  if (std::regex_search(load.dom, errors, std::regex("data-errors=\"([^\"]*)\""))) {
    trouble += errors[1].str();
  }
  if (load.dom.find("data-ready=") == std::string::npos) trouble += "script did not finish";
  return trouble;
}

TEST_F(ViewerInBrowser, PageLoadsWithoutNetworkAndWithoutConsoleMessages) {
  const auto load =
      HeadlessChromium::DumpDom(FileUrl(example_->page) +
                                    "#layers=grid,clean,hugging,voronoi,topology,rooms,"
                                    "areas,passages,widths&select=passage/0",
                                /*settle_ms=*/5000);
  SKIP_UNLESS_BROWSER_RAN(load.exit_code == 0);
  ASSERT_EQ(load.exit_code, 0);
  EXPECT_EQ(TroubleOf(load), "") << (HeadlessChromium::Offline() ? "offline" : "online");
  // The cleaning layer was coloured after loading, into a data: URL.
  EXPECT_TRUE(std::regex_search(
      load.dom, std::regex("class=\"clean-image\"[^>]*href=\"data:image/png;base64,")));

  // The same check catches a page that tries to fetch something.
  std::string page = ReadFile(example_->page);
  const size_t body = page.find("<div id=\"app\">");
  ASSERT_NE(body, std::string::npos);
  page.insert(body, "<img src=\"http://192.0.2.1/probe.png\">");
  testing::WriteFile(example_->dir.File("fetching.html"), page);
  const auto fetching = HeadlessChromium::DumpDom(FileUrl(example_->dir.File("fetching.html")));
  EXPECT_NE(TroubleOf(fetching).find("192.0.2.1"), std::string::npos) << TroubleOf(fetching);
}

// Drives the page with synthetic mouse events (a wheel turn, a drag, a hover
// and a click on the first area) from a script added after the viewer's,
// and leaves what happened on <body data-probe="...">.
constexpr char kMouseProbe[] = R"(<script>
(function () {
  const svg = document.querySelector('.view svg');
  const viewport = svg.querySelector('g.viewport');
  const scale = () => Number(/scale\(([^)]*)\)/.exec(viewport.getAttribute('transform'))[1]);
  const translate = () => /translate\(([^ ]*) ([^)]*)\)/.exec(viewport.getAttribute('transform')).slice(1).map(Number);
  const metres = () => Number(svg.querySelector('g.scalebar').dataset.metres);
  const box = svg.getBoundingClientRect();
  const at = (x, y) => ({ clientX: box.left + x, clientY: box.top + y, bubbles: true, cancelable: true, button: 0, pointerId: 1 });
  const probe = { scale0: scale(), metres0: metres() };
  svg.dispatchEvent(new WheelEvent('wheel', Object.assign({ deltaY: -600 }, at(200, 150))));
  probe.scale1 = scale();
  probe.metres1 = metres();
  const before = translate();
  svg.dispatchEvent(new PointerEvent('pointerdown', at(300, 300)));
  svg.dispatchEvent(new PointerEvent('pointermove', at(360, 330)));
  svg.dispatchEvent(new PointerEvent('pointerup', at(360, 330)));
  const after = translate();
  probe.panned = [after[0] - before[0], after[1] - before[1]];
  const area = document.querySelector('path.area');
  area.dispatchEvent(new PointerEvent('pointermove', at(0, 0)));
  probe.hoverInfo = document.getElementById('info').dataset.selected;
  probe.hovering = document.getElementById('info').dataset.hovering;
  probe.hashAfterHover = location.hash;
  area.dispatchEvent(new PointerEvent('pointerdown', at(0, 0)));
  area.dispatchEvent(new PointerEvent('pointerup', at(0, 0)));
  probe.hashAfterClick = location.hash;
  probe.area = area.dataset.id;
  document.body.dataset.probe = JSON.stringify(probe);
})();
</script>)";

TEST_F(ViewerInBrowser, WheelZoomsDragPansHoverShowsAndClickSelects) {
  std::string page = ReadFile(example_->page);
  const size_t end = page.rfind("</body>");
  ASSERT_NE(end, std::string::npos);
  page.insert(end, kMouseProbe);
  testing::WriteFile(example_->dir.File("probe.html"), page);
  const auto load = HeadlessChromium::DumpDom(FileUrl(example_->dir.File("probe.html")));
  SKIP_UNLESS_BROWSER_RAN(load.exit_code == 0);
  ASSERT_EQ(TroubleOf(load), "");
  std::smatch match;
  ASSERT_TRUE(std::regex_search(load.dom, match, std::regex("data-probe=\"([^\"]*)\"")));
  google::protobuf::Struct probe;
  const std::string json = std::regex_replace(match[1].str(), std::regex("&quot;"), "\"");
  ASSERT_TRUE(google::protobuf::util::JsonStringToMessage(json, &probe).ok()) << json;
  const auto& fields = probe.fields();
  const auto number = [&](const char* key) { return fields.at(key).number_value(); };
  // The wheel zooms in, and the scale bar shows fewer metres.
  EXPECT_GT(number("scale1"), number("scale0") * 1.5);
  EXPECT_LT(number("metres1"), number("metres0"));
  // The drag moves the map by the mouse's way.
  const auto& panned = fields.at("panned").list_value();
  EXPECT_DOUBLE_EQ(panned.values(0).number_value(), 60);
  EXPECT_DOUBLE_EQ(panned.values(1).number_value(), 30);
  // Hovering shows the area without selecting it; a click selects it.
  const std::string area = "area/" + fields.at("area").string_value();
  EXPECT_EQ(fields.at("hoverInfo").string_value(), area);
  EXPECT_EQ(fields.at("hovering").string_value(), "yes");
  EXPECT_EQ(fields.at("hashAfterHover").string_value().find("select="), std::string::npos);
  EXPECT_NE(fields.at("hashAfterClick").string_value().find("select=" + area), std::string::npos);
}

TEST_F(ViewerInBrowser, DiffViewShowsBothRunsSideBySide) {
  ASSERT_FALSE(example_->other_merge_key.empty());
  const auto load = HeadlessChromium::DumpDom(FileUrl(example_->diff_page) + "#view=side");
  SKIP_UNLESS_BROWSER_RAN(load.exit_code == 0);
  ASSERT_EQ(load.exit_code, 0);
  EXPECT_EQ(TroubleOf(load), "");
  EXPECT_EQ(CountOccurrences(load.dom, "class=\"view\""), 2);
  EXPECT_NE(load.dom.find("data-run=\"B\""), std::string::npos);
  // Each view draws its own run's areas: A's count plus B's.
  std::unique_ptr<ArtifactStore> store = OpenArtifactStore(example_->store, StoreMode::kReadOnly);
  const auto other =
      ReadArtifactAs<proto::AreaGraph>(*store, "office_small", example_->other_merge_key);
  ASSERT_NE(other.areas_size(), example_->graph.areas_size());
  EXPECT_EQ(CountOccurrences(load.dom, "class=\"area\""),
            example_->graph.areas_size() + other.areas_size());
  // The options that differ are marked.
  EXPECT_NE(load.dom.find("class=\"non-default differs\""), std::string::npos);

  const auto overlay = HeadlessChromium::DumpDom(FileUrl(example_->diff_page) + "#view=overlay");
  ASSERT_EQ(overlay.exit_code, 0);
  EXPECT_EQ(CountOccurrences(overlay.dom, "class=\"view\""), 1);
  EXPECT_EQ(CountOccurrences(overlay.dom, "class=\"area-outline\""), other.areas_size());
}

}  // namespace
}  // namespace areagraph

// ag-run --report DIR: one viewer page per map and a sortable index, for the
// shipped examples and one broken file.
#include "tools/report/collection_report.h"

#include <google/protobuf/util/json_util.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <map>
#include <memory>
#include <regex>
#include <string>
#include <vector>

#include "proto/artifacts.pb.h"
#include "stages/pipeline/stage.h"
#include "store/artifact_store.h"
#include "tests/support/headless_chromium.h"
#include "tests/support/test_support.h"
#include "tools/report/collection_index.pb.h"

namespace areagraph {
namespace {

using testing::FileUrl;
using testing::HeadlessChromium;
using testing::ReadFile;
using testing::RunTool;
using testing::TempDir;

TEST(MapPageFileName, KeepsSafeCharactersAndStaysUnique) {
  std::vector<std::string> taken;
  EXPECT_EQ(MapPageFileName("office_small", &taken), "maps/office_small.html");
  EXPECT_EQ(MapPageFileName("bormann/lab a", &taken), "maps/bormann_lab_a.html");
  EXPECT_EQ(MapPageFileName("bormann_lab_a", &taken), "maps/bormann_lab_a-2.html");
  EXPECT_EQ(MapPageFileName("Office_Small", &taken), "maps/Office_Small-2.html");
  EXPECT_EQ(MapPageFileName("../up", &taken), "maps/_.._up.html");
  EXPECT_EQ(MapPageFileName("", &taken), "maps/_.html");
}

// The index's JSON blob, read back.
report::CollectionIndex ReadIndex(const std::string& path) {
  const std::string html = ReadFile(path);
  std::smatch blob;
  report::CollectionIndex index;
  if (std::regex_search(html, blob, std::regex("id=\"index-data\">([^<]*)</script>"))) {
    EXPECT_TRUE(google::protobuf::util::JsonStringToMessage(blob[1].str(), &index).ok());
  }
  return index;
}

// Two example maps and a file that is no image, run with --report.
class RunReport : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    shared_ = new Shared();
    const std::string maps = shared_->dir.File("maps");
    std::filesystem::create_directories(maps);
    for (const char* name : {"two_rooms.png", "corridor_rooms.png"}) {
      std::filesystem::copy_file(testing::SourcePath(std::string("examples/") + name),
                                 maps + "/" + name);
    }
    testing::WriteFile(maps + "/broken.png", "not a png");
    shared_->run = RunTool(
        "ag-run", {"--store", shared_->store, "--jobs", "2", "--report", shared_->report, maps});
  }
  static void TearDownTestSuite() { delete shared_; }

  struct Shared {
    TempDir dir;
    std::string store = dir.File("areagraph.db");
    std::string report = dir.File("report");
    testing::CommandResult run;
  };
  static Shared* shared_;
};

RunReport::Shared* RunReport::shared_ = nullptr;

TEST_F(RunReport, WritesAPagePerMapAndAnIndexRowPerMap) {
  EXPECT_EQ(shared_->run.exit_code, 1) << shared_->run.err;  // broken.png failed
  EXPECT_NE(shared_->run.err.find("report/index.html (2 map pages, 1 failed)"), std::string::npos)
      << shared_->run.err;
  const report::CollectionIndex index = ReadIndex(shared_->report + "/index.html");
  ASSERT_EQ(index.rows_size(), 3);
  std::unique_ptr<ArtifactStore> store = OpenArtifactStore(shared_->store, StoreMode::kReadOnly);
  std::map<std::string, const report::MapRow*> rows;
  for (const report::MapRow& row : index.rows()) rows[row.map_name()] = &row;
  for (const std::string name : {"two_rooms", "corridor_rooms"}) {
    ASSERT_TRUE(rows.count(name)) << name;
    const report::MapRow& row = *rows[name];
    const auto graph = ReadHeadArtifact<proto::AreaGraph>(*store, name, kMergeStage);
    EXPECT_EQ(row.areas(), graph.areas_size());
    EXPECT_EQ(row.passages(), graph.passages_size());
    EXPECT_TRUE(row.has_area_graph());
    EXPECT_GT(row.room_width_m(), 0.5);
    EXPECT_GT(row.compute_s(), 0);
    EXPECT_TRUE(row.failure().empty());
    EXPECT_EQ(row.page(), "maps/" + name + ".html");
    EXPECT_GT(row.thumbnail_png().size(), 100u);
    const std::string page = ReadFile(shared_->report + "/" + row.page());
    EXPECT_NE(page.find("\"map_name\":\"" + name + "\""), std::string::npos);
  }
  ASSERT_TRUE(rows.count("broken"));
  EXPECT_EQ(rows["broken"]->failed_stage(), "import");
  EXPECT_FALSE(rows["broken"]->failure().empty());
  EXPECT_TRUE(rows["broken"]->page().empty());
}

TEST_F(RunReport, IndexSortsByTheColumnInTheFragment) {
  const report::CollectionIndex index = ReadIndex(shared_->report + "/index.html");
  const auto load =
      HeadlessChromium::DumpDom(FileUrl(shared_->report + "/index.html") + "#sort=-areas");
  if (load.exit_code != 0 && !HeadlessChromium::Unavailable().empty()) {
    GTEST_SKIP() << HeadlessChromium::Unavailable();
  }
  ASSERT_EQ(load.exit_code, 0);
  EXPECT_EQ(load.console, "");
  EXPECT_NE(load.dom.find("data-sort=\"-areas\""), std::string::npos);
  std::vector<std::string> order;
  const std::regex row("<tr[^>]*data-map=\"([^\"]*)\"");
  for (auto it = std::sregex_iterator(load.dom.begin(), load.dom.end(), row);
       it != std::sregex_iterator(); ++it) {
    order.push_back((*it)[1]);
  }
  // Most areas first; the broken map, which has none, last.
  std::map<std::string, int> areas;
  for (const report::MapRow& map : index.rows()) areas[map.map_name()] = map.areas();
  ASSERT_EQ(order.size(), 3u);
  EXPECT_GE(areas[order[0]], areas[order[1]]);
  EXPECT_NE(areas[order[0]], areas[order[1]]);
  EXPECT_EQ(order[2], "broken");

  const auto by_name =
      HeadlessChromium::DumpDom(FileUrl(shared_->report + "/index.html") + "#sort=name");
  ASSERT_EQ(by_name.exit_code, 0);
  ASSERT_NE(by_name.dom.find("data-map=\"two_rooms\""), std::string::npos);
  EXPECT_LT(by_name.dom.find("data-map=\"broken\""), by_name.dom.find("data-map=\"two_rooms\""));
}

TEST_F(RunReport, UnwritableReportFolderIsOneLine) {
  const std::string blocker = shared_->dir.File("file");
  testing::WriteFile(blocker, "x");
  const auto run = RunTool("ag-run", {"--store", shared_->store, "--report", blocker + "/report",
                                      testing::SourcePath("examples/two_rooms.png")});
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_NE(run.err.find("cannot make the report folder"), std::string::npos) << run.err;
  EXPECT_EQ(run.err.find("ag-run: report:"), std::string::npos) << run.err;
}

}  // namespace
}  // namespace areagraph

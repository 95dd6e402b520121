// ag-import end to end: what it prints, what it stores, and when it reuses
// what is stored.
#include <gtest/gtest.h>

#include <opencv2/imgcodecs.hpp>
#include <regex>
#include <string>

#include "stages/import/import_stage.h"
#include "store/artifact_store.h"
#include "store/digest.h"
#include "tests/stages/import/import_test_util.h"
#include "tests/support/test_support.h"

namespace areagraph {
namespace {

using testing::ArtifactCount;
using testing::CommandResult;
using testing::ReadFile;
using testing::ReadHeadGridMap;
using testing::RunTool;
using testing::SourcePath;
using testing::TempDir;
using testing::WriteTwoRoomPng;

class AgImportTest : public ::testing::Test {
 protected:
  void SetUp() override {
    image_ = dir_.File("two_rooms.png");
    store_ = dir_.File("store.db");
    WriteTwoRoomPng(image_);
  }

  CommandResult Import(std::vector<std::string> args) {
    args.insert(args.begin(), {"--store", store_});
    return RunTool("ag-import", args);
  }

  TempDir dir_;
  std::string image_;
  std::string store_;
};

TEST_F(AgImportTest, PrintsOneSummaryLineAndStoresTheGridMap) {
  const CommandResult run = Import({image_});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_EQ(run.err, "");
  EXPECT_TRUE(std::regex_match(
      run.out, std::regex("imported two_rooms: 240x140 px, 0\\.05 m/px, [0-9]+ occupied, [0-9]+ "
                          "free, [0-9]+ unknown \\(key [0-9a-f]{12}, stored\\)\n")))
      << run.out;

  std::string key;
  const proto::GridMap stored = ReadHeadGridMap(store_, "two_rooms", &key);
  const proto::GridMap expected = ImportGridMap(ReadImportSource(image_), proto::ImportOptions());
  EXPECT_EQ(stored.cells(), expected.cells());
  EXPECT_EQ(stored.frame().SerializeAsString(), expected.frame().SerializeAsString());
  EXPECT_EQ(stored.format_version(), 1u);
  EXPECT_EQ(stored.source_path(), image_);
  EXPECT_EQ(stored.source_digest(), Sha256Hex(ReadFile(image_)));
  EXPECT_NE(run.out.find("(key " + key.substr(0, 12) + ","), std::string::npos);

  const std::optional<MapRecord> map = OpenArtifactStore(store_)->ReadMap("two_rooms");
  ASSERT_TRUE(map);
  EXPECT_EQ(map->source_path, image_);
  EXPECT_EQ(map->source_digest, stored.source_digest());
}

// A BMP goes through libag_image_codecs.so, which brings the shared OpenCV
// into an ag-import that links OpenCV statically (cmake/FastStart.cmake): the
// decoded picture crosses from one copy to the other.
TEST_F(AgImportTest, DecodesABmpThroughTheCodecsModule) {
  const std::string bmp = dir_.File("two_rooms.bmp");
  ASSERT_TRUE(cv::imwrite(bmp, cv::imread(image_, cv::IMREAD_UNCHANGED)));
  const CommandResult run = Import({bmp});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const proto::GridMap stored = ReadHeadGridMap(store_, "two_rooms");
  const proto::GridMap expected = ImportGridMap(ReadImportSource(image_), proto::ImportOptions());
  EXPECT_EQ(stored.frame().width_px(), 240);
  EXPECT_EQ(stored.cells(), expected.cells());
}

TEST_F(AgImportTest, SecondImportIsCached) {
  ASSERT_EQ(Import({image_}).exit_code, 0);
  std::string first_key;
  ReadHeadGridMap(store_, "two_rooms", &first_key);
  const CommandResult again = Import({image_});
  ASSERT_EQ(again.exit_code, 0) << again.err;
  EXPECT_NE(again.out.find(", cached)"), std::string::npos) << again.out;
  EXPECT_EQ(ArtifactCount(store_, "two_rooms"), 1u);
  std::string second_key;
  ReadHeadGridMap(store_, "two_rooms", &second_key);
  EXPECT_EQ(second_key, first_key);
}

TEST_F(AgImportTest, ChangedFileReplacesTheHeadAndOldContentIsCachedAgain) {
  ASSERT_EQ(Import({image_}).exit_code, 0);
  std::string open_key;
  const proto::GridMap open_door = ReadHeadGridMap(store_, "two_rooms", &open_key);

  WriteTwoRoomPng(image_, /*door_open=*/false);
  const CommandResult changed = Import({image_});
  ASSERT_EQ(changed.exit_code, 0) << changed.err;
  EXPECT_NE(changed.out.find(", stored)"), std::string::npos) << changed.out;
  std::string closed_key;
  const proto::GridMap closed_door = ReadHeadGridMap(store_, "two_rooms", &closed_key);
  EXPECT_NE(closed_key, open_key);
  EXPECT_NE(closed_door.cells(), open_door.cells());
  EXPECT_EQ(closed_door.source_digest(), Sha256Hex(ReadFile(image_)));
  EXPECT_EQ(ArtifactCount(store_, "two_rooms"), 2u);

  WriteTwoRoomPng(image_, /*door_open=*/true);
  const CommandResult back = Import({image_});
  EXPECT_NE(back.out.find(", cached)"), std::string::npos) << back.out;
  std::string back_key;
  ReadHeadGridMap(store_, "two_rooms", &back_key);
  EXPECT_EQ(back_key, open_key);
  EXPECT_EQ(ArtifactCount(store_, "two_rooms"), 2u);
}

TEST_F(AgImportTest, OptionsEnterTheCacheKey) {
  ASSERT_EQ(Import({image_}).exit_code, 0);
  const CommandResult changed = Import({"--set", "import.free_min_grey=200", image_});
  ASSERT_EQ(changed.exit_code, 0) << changed.err;
  EXPECT_NE(changed.out.find(", stored)"), std::string::npos) << changed.out;
  EXPECT_EQ(ArtifactCount(store_, "two_rooms"), 2u);
}

TEST_F(AgImportTest, ResolutionFlagSetsTheFrame) {
  const CommandResult run = Import({"--resolution", "0.1", image_});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_NE(run.out.find(" 0.1 m/px"), std::string::npos) << run.out;
  EXPECT_DOUBLE_EQ(ReadHeadGridMap(store_, "two_rooms").frame().resolution_m(), 0.1);
}

TEST_F(AgImportTest, ForceRecomputesWithoutAddingArtifacts) {
  ASSERT_EQ(Import({image_}).exit_code, 0);
  const CommandResult forced = Import({"--force", image_});
  ASSERT_EQ(forced.exit_code, 0) << forced.err;
  EXPECT_NE(forced.out.find(", stored)"), std::string::npos) << forced.out;
  EXPECT_EQ(ArtifactCount(store_, "two_rooms"), 1u);
}

TEST_F(AgImportTest, NameOrMapChoosesTheMapName) {
  ASSERT_EQ(Import({"--name", "lab", image_}).exit_code, 0);
  ASSERT_EQ(Import({"--map", "other", image_}).exit_code, 0);
  EXPECT_EQ(ReadHeadGridMap(store_, "lab").frame().width_px(), 240);
  EXPECT_EQ(ReadHeadGridMap(store_, "other").frame().width_px(), 240);
  const CommandResult both = Import({"--name", "a", "--map", "b", image_});
  EXPECT_EQ(both.exit_code, 2);
  EXPECT_EQ(testing::CountLines(both.err), 1) << both.err;
}

TEST_F(AgImportTest, MapServerYamlGivenAsTheImage) {
  const CommandResult run = Import({SourcePath("examples/office_small.yaml")});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_EQ(run.out.rfind("imported office_small: 360x300 px, 0.05 m/px,", 0), 0u) << run.out;
  const proto::GridMap grid = ReadHeadGridMap(store_, "office_small");
  EXPECT_DOUBLE_EQ(grid.frame().origin_x_m(), -2.0);
  EXPECT_DOUBLE_EQ(grid.frame().origin_y_m(), -1.5);
  EXPECT_EQ(grid.source_digest(), Sha256Hex(ReadFile(SourcePath("examples/office_small.png")) +
                                            ReadFile(SourcePath("examples/office_small.yaml"))));
  // Given as the PNG, the YAML beside it is used: same bytes, same key.
  const CommandResult png = Import({SourcePath("examples/office_small.png")});
  EXPECT_NE(png.out.find(", cached)"), std::string::npos) << png.out;
}

TEST_F(AgImportTest, HelpExitsZero) {
  const CommandResult help = RunTool("ag-import", {"--help"});
  EXPECT_EQ(help.exit_code, 0);
  EXPECT_NE(help.out.find("--resolution"), std::string::npos);
  EXPECT_NE(help.out.find("--name"), std::string::npos);
}

}  // namespace
}  // namespace areagraph

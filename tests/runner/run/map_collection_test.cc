#include "runner/run/map_collection.h"

#include <gtest/gtest.h>

#include <filesystem>

#include "common/error.h"
#include "runner/run/manifest_reader.h"
#include "tests/support/test_support.h"

namespace areagraph {
namespace {

using testing::ErrorOf;
using testing::TempDir;
using testing::WriteFile;

TEST(MapCollectionTest, DirectoryIsSearchedRecursivelyAndNamedByRelativePath) {
  TempDir dir;
  std::filesystem::create_directories(dir.File("floor1/wing"));
  WriteFile(dir.File("b.png"), "x");
  WriteFile(dir.File("floor1/wing/a.pgm"), "x");
  WriteFile(dir.File("floor1/notes.txt"), "x");
  WriteFile(dir.File("floor1/a.yaml"), "x");
  const std::vector<MapEntry> maps = CollectMaps({dir.path()});
  ASSERT_EQ(maps.size(), 2u);
  EXPECT_EQ(maps[0].name, "b");
  EXPECT_EQ(maps[1].name, "floor1/wing/a");
  EXPECT_EQ(maps[1].path, dir.File("floor1/wing/a.pgm"));
}

TEST(MapCollectionTest, SameNameTwiceIsRefused) {
  TempDir dir;
  std::filesystem::create_directories(dir.File("x"));
  WriteFile(dir.File("a.png"), "x");
  WriteFile(dir.File("x/a.png"), "x");
  const std::string error = ErrorOf<InputError>([&] {
    CollectMaps({dir.File("a.png"), dir.File("x/a.png")});
  });
  EXPECT_NE(error.find("second map named 'a'"), std::string::npos) << error;
}

TEST(MapCollectionTest, MissingPathIsRefused) {
  const std::string error = ErrorOf<InputError>([] { CollectMaps({"/no/such/map.png"}); });
  EXPECT_NE(error.find("/no/such/map.png"), std::string::npos) << error;
}

TEST(MapCollectionTest, TsvManifestGivesNamesPathsAndOptions) {
  TempDir dir;
  WriteFile(dir.File("list.tsv"),
            "# maps of floor 2\npath\tname\tcut.room_width_m\n"
            "a.png\tfirst\t1.1\n\nsub/b.png\t\t\n");
  const std::vector<MapEntry> maps = CollectMaps({dir.File("list.tsv")});
  ASSERT_EQ(maps.size(), 2u);
  EXPECT_EQ(maps[0].name, "first");
  EXPECT_EQ(maps[0].path, dir.File("a.png"));
  EXPECT_EQ(maps[0].overrides, std::vector<std::string>{"cut.room_width_m=1.1"});
  EXPECT_EQ(maps[0].origin, dir.File("list.tsv") + ":3");
  EXPECT_EQ(maps[1].name, "b");
  EXPECT_TRUE(maps[1].overrides.empty());
  const proto::PipelineOptions options = OptionsForMap(proto::PipelineOptions(), maps[0]);
  EXPECT_DOUBLE_EQ(options.cut().room_width_m(), 1.1);
}

TEST(MapCollectionTest, CsvManifestHonoursQuotes) {
  TempDir dir;
  WriteFile(dir.File("list.csv"), "name,path\n\"north, wing\",\"/maps/a b.png\"\n");
  const ManifestTable table = ReadManifest(dir.File("list.csv"));
  ASSERT_EQ(table.rows.size(), 1u);
  EXPECT_EQ(table.rows[0].cells, (std::vector<std::string>{"north, wing", "/maps/a b.png"}));
}

TEST(MapCollectionTest, ManifestExtensionInAnyCaseSelectsTheFormat) {
  TempDir dir;
  WriteFile(dir.File("list.Csv"), "path,name\na.png,first\n");
  const std::vector<MapEntry> maps = CollectMaps({dir.File("list.Csv")});
  ASSERT_EQ(maps.size(), 1u);
  EXPECT_EQ(maps[0].name, "first");
  EXPECT_EQ(maps[0].path, dir.File("a.png"));
}

TEST(MapCollectionTest, ManifestRowOfWrongWidthNamesItsLine) {
  TempDir dir;
  WriteFile(dir.File("list.csv"), "path,name\na.png,a\nb.png\n");
  const std::string error = ErrorOf<InputError>([&] { CollectMaps({dir.File("list.csv")}); });
  EXPECT_NE(error.find("list.csv:3: 1 fields, but the header has 2"), std::string::npos) << error;
}

TEST(MapCollectionTest, ManifestWithoutPathColumnIsRefused) {
  TempDir dir;
  WriteFile(dir.File("list.tsv"), "file\tname\na.png\ta\n");
  const std::string error = ErrorOf<InputError>([&] { CollectMaps({dir.File("list.tsv")}); });
  EXPECT_NE(error.find("no `path` column"), std::string::npos) << error;
}

TEST(MapCollectionTest, ManifestColumnThatIsNoOptionListsTheValidKeys) {
  TempDir dir;
  WriteFile(dir.File("list.tsv"), "path\tcut.room_widht_m\na.png\t1\n");
  const std::string error = ErrorOf<OptionsError>([&] { CollectMaps({dir.File("list.tsv")}); });
  EXPECT_NE(error.find("'cut.room_widht_m' is not an option"), std::string::npos) << error;
  EXPECT_NE(error.find("cut.room_width_m"), std::string::npos) << error;
}

TEST(MapCollectionTest, ManifestValueOfWrongTypeNamesTheRow) {
  TempDir dir;
  WriteFile(dir.File("list.tsv"), "path\tcut.room_width_m\na.png\twide\n");
  const std::vector<MapEntry> maps = CollectMaps({dir.File("list.tsv")});
  ASSERT_EQ(maps.size(), 1u);
  const std::string error =
      ErrorOf<OptionsError>([&] { OptionsForMap(proto::PipelineOptions(), maps[0]); });
  EXPECT_NE(error.find("list.tsv:2"), std::string::npos) << error;
}

TEST(MapCollectionTest, BinaryManifestIsRefused) {
  TempDir dir;
  WriteFile(dir.File("list.tsv"), std::string("path\n\0\x01\x02", 8));
  const std::string error = ErrorOf<InputError>([&] { CollectMaps({dir.File("list.tsv")}); });
  EXPECT_NE(error.find("list.tsv:2"), std::string::npos) << error;
}

// Excel saves "CSV UTF-8" with a byte order mark before the first column name.
TEST(MapCollectionTest, ManifestWithAByteOrderMarkIsRead) {
  TempDir dir;
  WriteFile(dir.File("list.csv"), "\xEF\xBB\xBFpath,name\na.png,first\n");
  const std::vector<MapEntry> maps = CollectMaps({dir.File("list.csv")});
  ASSERT_EQ(maps.size(), 1u);
  EXPECT_EQ(maps[0].name, "first");
  WriteFile(dir.File("list.tsv"), "\xEF\xBB\xBFpath\na.png\n");
  EXPECT_EQ(CollectMaps({dir.File("list.tsv")}).at(0).name, "a");
}

TEST(MapCollectionTest, HeaderOnlyManifestIsRefused) {
  TempDir dir;
  WriteFile(dir.File("list.tsv"), "path\tname\n# nothing yet\n\n");
  EXPECT_EQ(ErrorOf<InputError>([&] { CollectMaps({dir.File("list.tsv")}); }),
            "manifest '" + dir.File("list.tsv") + "' lists no maps (it has only its header)");
}

TEST(MapCollectionTest, DirectoryWithoutImagesIsRefusedEvenBesideOthers) {
  TempDir dir;
  std::filesystem::create_directories(dir.File("empty/sub"));
  WriteFile(dir.File("empty/sub/notes.txt"), "x");
  WriteFile(dir.File("a.png"), "x");
  const std::string error = ErrorOf<InputError>([&] {
    CollectMaps({dir.File("a.png"), dir.File("empty")});
  });
  EXPECT_EQ(error.rfind("directory '" + dir.File("empty") + "' holds no map images", 0), 0u)
      << error;
}

TEST(MapCollectionTest, ManifestNumbersThatAreNotFiniteOrAbsurdNameTheRow) {
  TempDir dir;
  WriteFile(dir.File("list.csv"),
            "path,name,cut.room_width_m,cut.room_width_open_doors\n"
            "a.png,a,nan,true\nb.png,b,1e308,TRUE\nc.png,c,1.2,T\n");
  const std::vector<MapEntry> maps = CollectMaps({dir.File("list.csv")});
  ASSERT_EQ(maps.size(), 3u);
  for (int row = 0; row < 3; ++row) {
    const std::string error =
        ErrorOf<OptionsError>([&] { OptionsForMap(proto::PipelineOptions(), maps[row]); });
    EXPECT_NE(error.find("list.csv:" + std::to_string(row + 2)), std::string::npos) << error;
  }
}

}  // namespace
}  // namespace areagraph

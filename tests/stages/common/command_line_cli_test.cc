// Runs the executables as a user would: --help, and the store-related bad
// input that every tool shares. Each bad case must give one line on stderr,
// a non-zero exit, and leave the store exactly as it was.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>

#include "tests/support/test_support.h"

namespace areagraph::testing {
namespace {

// A small valid map: a walled room.
std::string WriteRoomImage(const TempDir& dir) {
  cv::Mat image(40, 60, CV_8UC1, cv::Scalar(0));
  image(cv::Rect(2, 2, 56, 36)).setTo(254);
  const std::string path = dir.File("room.png");
  cv::imwrite(path, image);
  return path;
}

// The logical content of a store, as sqlite3's .dump prints it.
std::string DumpStore(const std::string& store) {
  const CommandResult dump = RunProgram({"sqlite3", store, ".dump"});
  EXPECT_EQ(dump.exit_code, 0) << dump.err;
  return dump.out;
}

void ExpectOneLineError(const CommandResult& result, const std::string& needle) {
  EXPECT_NE(result.exit_code, 0);
  EXPECT_EQ(result.signal, 0) << "killed by a signal";
  EXPECT_EQ(CountLines(result.err), 1) << result.err;
  EXPECT_NE(result.err.find(needle), std::string::npos) << result.err;
}

TEST(CliTest, EveryExecutableHasHelp) {
  std::vector<std::string> tools;
  for (const auto& entry : std::filesystem::directory_iterator(AG_BIN_DIR)) {
    const std::string name = entry.path().filename().string();
    if (name.rfind("ag-", 0) == 0) tools.push_back(name);
  }
  for (const char* required : {"ag-import", "ag-inspect"}) {
    EXPECT_NE(std::find(tools.begin(), tools.end(), required), tools.end()) << required;
  }
  for (const std::string& tool : tools) {
    const CommandResult help = RunTool(tool, {"--help"});
    EXPECT_EQ(help.exit_code, 0) << tool << ": " << help.err;
    EXPECT_NE(help.out.find("--help"), std::string::npos) << tool;
    EXPECT_NE(help.out.find("--version"), std::string::npos) << tool;
    const CommandResult version = RunTool(tool, {"--version"});
    EXPECT_EQ(version.exit_code, 0) << tool << ": " << version.err;
    EXPECT_EQ(version.out.rfind(tool + ": areagraph ", 0), 0u) << version.out;
    EXPECT_EQ(CountLines(version.out), 1) << version.out;
  }
}

TEST(CliTest, ImportThenInspect) {
  TempDir dir;
  const std::string image = WriteRoomImage(dir), store = dir.File("s.db");
  const CommandResult imported = RunTool("ag-import", {"--store", store, image});
  ASSERT_EQ(imported.exit_code, 0) << imported.err;
  const CommandResult maps = RunTool("ag-inspect", {"--store", store});
  ASSERT_EQ(maps.exit_code, 0) << maps.err;
  EXPECT_NE(maps.out.find("room"), std::string::npos) << maps.out;
  const CommandResult artifacts = RunTool("ag-inspect", {"--store", store, "--map", "room"});
  ASSERT_EQ(artifacts.exit_code, 0) << artifacts.err;
  EXPECT_NE(artifacts.out.find("import"), std::string::npos) << artifacts.out;
  EXPECT_NE(artifacts.out.find("*"), std::string::npos) << "the import is the head";
  const CommandResult summary =
      RunTool("ag-inspect", {"--store", store, "--map", "room", "--stage", "import"});
  ASSERT_EQ(summary.exit_code, 0) << summary.err;
  EXPECT_NE(summary.out.find("60x40 px"), std::string::npos) << summary.out;
  // 56x36 free cells inside a 2-pixel wall.
  EXPECT_NE(summary.out.find("2016 free"), std::string::npos) << summary.out;
  const CommandResult json =
      RunTool("ag-inspect", {"--store", store, "--map", "room", "--stage", "import", "--json"});
  ASSERT_EQ(json.exit_code, 0) << json.err;
  EXPECT_NE(json.out.find("\"width_px\": 60"), std::string::npos) << json.out;
  EXPECT_NE(json.out.find("\"format_version\": 1"), std::string::npos) << json.out;
}

TEST(CliTest, StoreInMissingDirectory) {
  TempDir dir;
  const std::string image = WriteRoomImage(dir);
  const std::string store = dir.File("no/such/dir/s.db");
  ExpectOneLineError(RunTool("ag-import", {"--store", store, image}), "s.db");
  EXPECT_FALSE(std::filesystem::exists(dir.File("no")));
  ExpectOneLineError(RunTool("ag-inspect", {"--store", store}), "s.db");
}

TEST(CliTest, StoreInReadOnlyDirectory) {
  TempDir dir;
  const std::string image = WriteRoomImage(dir);
  std::filesystem::create_directory(dir.File("ro"));
  const std::string store = dir.File("ro/s.db");
  CommandResult result;
  if (geteuid() != 0) {
    chmod(dir.File("ro").c_str(), 0555);
    result = RunTool("ag-import", {"--store", store, image});
  } else {
    // Root ignores permission bits; a read-only bind mount stops even root.
    const std::string script = "mount --bind -o ro '" + dir.File("ro") + "' '" + dir.File("ro") +
                               "' || exit 77; exec '" + std::string(AG_BIN_DIR) +
                               "/ag-import' --store '" + store + "' '" + image + "'";
    result = RunProgram({"unshare", "-m", "sh", "-c", script});
    if (result.exit_code == 77) GTEST_SKIP() << "cannot make a read-only mount here";
  }
  ExpectOneLineError(result, "s.db");
  EXPECT_FALSE(std::filesystem::exists(store));
}

TEST(CliTest, StoreThatIsNotSqlite) {
  TempDir dir;
  const std::string image = WriteRoomImage(dir), store = dir.File("s.db");
  const std::string text = "these are my notes, not a database\n";
  WriteFile(store, text);
  ExpectOneLineError(RunTool("ag-import", {"--store", store, image}), "s.db");
  ExpectOneLineError(RunTool("ag-inspect", {"--store", store}), "s.db");
  EXPECT_EQ(ReadFile(store), text);
}

TEST(CliTest, StoreFromNewerSchema) {
  TempDir dir;
  const std::string image = WriteRoomImage(dir), store = dir.File("s.db");
  ASSERT_EQ(RunTool("ag-import", {"--store", store, image}).exit_code, 0);
  ASSERT_EQ(RunProgram({"sqlite3", store, "PRAGMA user_version = 99;"}).exit_code, 0);
  const std::string before = DumpStore(store);
  const CommandResult result = RunTool("ag-import", {"--store", store, "--name", "x", image});
  ExpectOneLineError(result, "newer");
  ExpectOneLineError(RunTool("ag-inspect", {"--store", store}), "newer");
  EXPECT_EQ(DumpStore(store), before);
  EXPECT_EQ(RunProgram({"sqlite3", store, "PRAGMA user_version;"}).out, "99\n");
}

TEST(CliTest, UnknownSetKeyAndBadValue) {
  TempDir dir;
  const std::string image = WriteRoomImage(dir), store = dir.File("s.db");
  ASSERT_EQ(RunTool("ag-import", {"--store", store, image}).exit_code, 0);
  const std::string before = DumpStore(store);
  const CommandResult unknown = RunTool(
      "ag-import", {"--store", store, "--name", "y", "--set", "import.resolutoin_m=0.1", image});
  ExpectOneLineError(unknown, "import.resolution_m");
  const CommandResult bad_value = RunTool(
      "ag-import", {"--store", store, "--name", "y", "--set", "import.resolution_m=fine", image});
  ExpectOneLineError(bad_value, "expects a double");
  EXPECT_EQ(DumpStore(store), before);
}

TEST(CliTest, InspectUnknownMapAndMissingStore) {
  TempDir dir;
  const std::string image = WriteRoomImage(dir), store = dir.File("s.db");
  ASSERT_EQ(RunTool("ag-import", {"--store", store, image}).exit_code, 0);
  ExpectOneLineError(RunTool("ag-inspect", {"--store", store, "--map", "nope"}), "nope");
  ExpectOneLineError(RunTool("ag-inspect", {"--store", dir.File("missing.db")}), "missing.db");
  EXPECT_FALSE(std::filesystem::exists(dir.File("missing.db")));
}

}  // namespace
}  // namespace areagraph::testing

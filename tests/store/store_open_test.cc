#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <set>
#include <string>

#include "common/error.h"
#include "store/artifact_store.h"
#include "tests/support/raw_sqlite.h"
#include "tests/support/test_support.h"

namespace areagraph {
namespace {

using testing::MakeArtifact;
using testing::ReadFile;
using testing::TempDir;
using testing::WriteFile;

// The message of the StoreError that opening `path` throws ("" if none).
std::string OpenError(const std::string& path, StoreMode mode = StoreMode::kReadWrite) {
  try {
    OpenArtifactStore(path, mode);
  } catch (const StoreError& error) {
    return error.what();
  }
  return "";
}

std::set<std::string> FileNames(const std::string& dir) {
  std::set<std::string> names;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    names.insert(entry.path().filename().string());
  }
  return names;
}

// Root ignores permission bits, so a chmod-based test cannot fail to write.
bool CanWriteDespiteMode(const std::string& path) {
  return geteuid() == 0 || access(path.c_str(), W_OK) == 0;
}

TEST(StoreOpenTest, TextFileIsRejectedAndLeftUnchanged) {
  TempDir dir;
  const std::string path = dir.File("notes.db");
  std::string text;
  for (int i = 0; i < 100; ++i) text += "line " + std::to_string(i) + " of a text file\n";
  WriteFile(path, text);
  for (StoreMode mode : {StoreMode::kReadWrite, StoreMode::kReadOnly}) {
    EXPECT_EQ(OpenError(path, mode),
              "'" + path + "' is not an areagraph store (not an SQLite database)");
    EXPECT_EQ(ReadFile(path), text);
    EXPECT_EQ(FileNames(dir.path()), std::set<std::string>{"notes.db"});  // no -wal, -shm
  }
}

TEST(StoreOpenTest, ShortTextFileIsRejectedAndLeftUnchanged) {
  TempDir dir;
  const std::string path = dir.File("short.db");
  WriteFile(path, "hello\n");
  EXPECT_NE(OpenError(path).find("not an SQLite database"), std::string::npos);
  EXPECT_EQ(ReadFile(path), "hello\n");
}

TEST(StoreOpenTest, ForeignSqliteDatabaseIsRejectedAndLeftUnchanged) {
  TempDir dir;
  const std::string path = dir.File("other.db");
  testing::ExecSql(path, "CREATE TABLE people (name TEXT); INSERT INTO people VALUES ('ada')");
  const std::string before = ReadFile(path);
  for (StoreMode mode : {StoreMode::kReadWrite, StoreMode::kReadOnly}) {
    EXPECT_EQ(OpenError(path, mode),
              "'" + path + "' is an SQLite database but not an areagraph store");
    EXPECT_EQ(ReadFile(path), before);
  }
  EXPECT_EQ(testing::QueryColumn(path, "PRAGMA journal_mode"), std::vector<std::string>{"delete"});
}

TEST(StoreOpenTest, NewerSchemaIsRejectedAndLeftUnchanged) {
  TempDir dir;
  const std::string path = dir.File("store.db");
  OpenArtifactStore(path)->WriteArtifact(MakeArtifact("m", "clean", "k", "payload"));
  testing::ExecSql(path, "PRAGMA user_version = 99");
  const std::string before = ReadFile(path);
  const std::set<std::string> files_before = FileNames(dir.path());
  for (StoreMode mode : {StoreMode::kReadWrite, StoreMode::kReadOnly}) {
    EXPECT_EQ(OpenError(path, mode),
              "store '" + path + "' has schema version 99, newer than this build's " +
                  std::to_string(kStoreSchemaVersion) + "; upgrade areagraph");
    EXPECT_EQ(ReadFile(path), before);
    if (mode == StoreMode::kReadWrite) {
      EXPECT_EQ(FileNames(dir.path()), files_before);
    } else {
      // A read-only connection to a WAL file may leave SQLite's shared-memory
      // index and an empty log behind (it may not delete them); no content.
      const std::string wal = path + "-wal";
      if (std::filesystem::exists(wal)) {
        EXPECT_EQ(std::filesystem::file_size(wal), 0u);
      }
    }
  }
}

TEST(StoreOpenTest, MissingDirectoryGivesOneClearError) {
  TempDir dir;
  const std::string path = dir.File("missing/sub/store.db");
  const std::string error = OpenError(path);
  EXPECT_EQ(error.rfind("cannot create store '" + path + "': ", 0), 0u) << error;
  EXPECT_NE(error.find("does not exist"), std::string::npos) << error;
  EXPECT_FALSE(std::filesystem::exists(dir.File("missing")));
}

TEST(StoreOpenTest, ReadOnlyDirectoryGivesOneClearError) {
  TempDir dir;
  const std::string locked = dir.File("locked");
  std::filesystem::create_directory(locked);
  chmod(locked.c_str(), 0555);
  if (CanWriteDespiteMode(locked)) {
    GTEST_SKIP() << "running as root (or on a file system that ignores modes): a read-only "
                    "directory cannot be made here";
  }
  const std::string path = locked + "/store.db";
  const std::string error = OpenError(path);
  EXPECT_EQ(error.rfind("cannot create store '" + path + "': ", 0), 0u) << error;
  EXPECT_NE(error.find("ermission denied"), std::string::npos) << error;
  EXPECT_TRUE(FileNames(locked).empty());
}

TEST(StoreOpenTest, ReadOnlyFileCannotBeOpenedForWriting) {
  TempDir dir;
  const std::string path = dir.File("store.db");
  OpenArtifactStore(path)->WriteArtifact(MakeArtifact("m", "clean", "k", "payload"));
  chmod(path.c_str(), 0444);
  if (CanWriteDespiteMode(path)) {
    GTEST_SKIP() << "running as root (or on a file system that ignores modes): a read-only "
                    "file cannot be made here";
  }
  EXPECT_EQ(OpenError(path), "cannot write store '" + path + "': the file is read-only");
  EXPECT_EQ(OpenArtifactStore(path, StoreMode::kReadOnly)->ReadHead("m", "clean")->payload,
            "payload");
}

TEST(StoreOpenTest, ReadOnlyModeNeverCreatesAFile) {
  TempDir dir;
  const std::string path = dir.File("store.db");
  EXPECT_EQ(OpenError(path, StoreMode::kReadOnly), "store '" + path + "' does not exist");
  EXPECT_TRUE(FileNames(dir.path()).empty());
}

TEST(StoreOpenTest, EmptyFileBecomesAStoreButNotInReadOnlyMode) {
  TempDir dir;
  const std::string path = dir.File("store.db");
  WriteFile(path, "");
  EXPECT_NE(OpenError(path, StoreMode::kReadOnly).find("is not an areagraph store"),
            std::string::npos);
  EXPECT_EQ(ReadFile(path), "");
  OpenArtifactStore(path)->WriteArtifact(MakeArtifact("m", "clean", "k", "payload"));
  EXPECT_EQ(OpenArtifactStore(path, StoreMode::kReadOnly)->ReadHead("m", "clean")->payload,
            "payload");
}

TEST(StoreOpenTest, ReopeningKeepsEverything) {
  TempDir dir;
  const std::string path = dir.File("store.db");
  for (int i = 0; i < 3; ++i) {
    OpenArtifactStore(path)->WriteArtifact(
        MakeArtifact("m", "clean", "k" + std::to_string(i), "p"));
  }
  EXPECT_EQ(OpenArtifactStore(path)->ReadArtifactSummaries("m").size(), 3u);
}

}  // namespace
}  // namespace areagraph

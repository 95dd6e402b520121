// A new store file is built under a temporary name and linked to its own
// once whole (store/sqlite_store_creation.cc): the same store as SQLite's
// own way to it, in one file sync instead of six.

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <memory>
#include <set>
#include <string>
#include <vector>

#include "store/artifact_store.h"
#include "store/sqlite_store_creation.h"
#include "tests/support/raw_sqlite.h"
#include "tests/support/test_support.h"

namespace areagraph {
namespace {

using testing::MakeArtifact;
using testing::QueryColumn;
using testing::TempDir;

std::set<std::string> FileNames(const std::string& dir) {
  std::set<std::string> names;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    names.insert(entry.path().filename().string());
  }
  return names;
}

// The file's schema, version and journal mode as SQLite reads them from a
// copy of the file alone (no log beside it).
std::vector<std::string> FileAlone(const std::string& store, const TempDir& elsewhere) {
  const std::string copy = elsewhere.File("alone.db");
  std::filesystem::copy_file(store, copy, std::filesystem::copy_options::overwrite_existing);
  std::vector<std::string> facts =
      QueryColumn(copy,
                  "SELECT type || ' ' || name || ': ' || coalesce(sql, '') "
                  "FROM sqlite_master ORDER BY name");
  facts.push_back("user_version " + QueryColumn(copy, "PRAGMA user_version")[0]);
  facts.push_back("journal_mode " + QueryColumn(copy, "PRAGMA journal_mode")[0]);
  return facts;
}

TEST(StoreCreationTest, NewFileHoldsTheWholeSchemaInWriteAheadModeAndNothingIsLeftBeside) {
  TempDir dir;
  TempDir elsewhere;
  const std::string fast = dir.File("new.db");
  {
    const std::unique_ptr<ArtifactStore> store = OpenArtifactStore(fast);
    // While it is open: the file alone is already a whole store; the
    // temporary name is gone.
    const std::vector<std::string> facts = FileAlone(fast, elsewhere);
    EXPECT_NE(std::find(facts.begin(), facts.end(),
                        "user_version " + std::to_string(kStoreSchemaVersion)),
              facts.end());
    EXPECT_NE(std::find(facts.begin(), facts.end(), "journal_mode wal"), facts.end());
    for (const std::string& name : FileNames(dir.path())) {
      EXPECT_TRUE(name == "new.db" || name == "new.db-wal" || name == "new.db-shm") << name;
    }
    store->WriteArtifact(MakeArtifact("m", "clean", "k", "payload"));
  }
  EXPECT_EQ(FileNames(dir.path()), std::set<std::string>{"new.db"});
  EXPECT_EQ(OpenArtifactStore(fast, StoreMode::kReadOnly)->ReadHead("m", "clean")->payload,
            "payload");

  // SQLite's own way, taken for an empty file that is already there: the
  // same tables, indexes, version and mode.
  const std::string slow = dir.File("empty.db");
  testing::WriteFile(slow, "");
  OpenArtifactStore(slow).reset();
  EXPECT_EQ(FileAlone(fast, elsewhere), FileAlone(slow, elsewhere));
}

TEST(StoreCreationTest, ExistingStoreIsOpenedNotReplaced) {
  TempDir dir;
  const std::string path = dir.File("s.db");
  OpenArtifactStore(path)->WriteArtifact(MakeArtifact("m", "clean", "k", "payload"));
  // A second writer opening the same path keeps what is there.
  OpenArtifactStore(path)->WriteArtifact(MakeArtifact("m", "cut", "k2", "more"));
  const std::unique_ptr<ArtifactStore> store = OpenArtifactStore(path, StoreMode::kReadOnly);
  EXPECT_EQ(store->ReadHead("m", "clean")->payload, "payload");
  EXPECT_EQ(store->ReadHead("m", "cut")->payload, "more");
}

TEST(StoreCreationTest, StrayTemporaryFileOfAKilledCreatorIsHarmless) {
  TempDir dir;
  const std::string path = dir.File("s.db");
  // What a creator killed before its link leaves: a partly built file under
  // the temporary name, no store.
  testing::WriteFile(path + ".new-1-0", "SQLite format 3");
  OpenArtifactStore(path)->WriteArtifact(MakeArtifact("m", "clean", "k", "payload"));
  EXPECT_EQ(OpenArtifactStore(path, StoreMode::kReadOnly)->ReadHead("m", "clean")->payload,
            "payload");
}

TEST(StoreCreationTest, CreateNewStoreFileSaysWhetherThisCallMadeTheStore) {
  TempDir dir;
  const std::string path = dir.File("s.db");
  ASSERT_TRUE(CreateNewStoreFile(path));
  // Made whole by this call: the current schema in WAL mode, nothing beside.
  EXPECT_EQ(FileNames(dir.path()), std::set<std::string>{"s.db"});
  EXPECT_EQ(QueryColumn(path, "PRAGMA user_version")[0], std::to_string(kStoreSchemaVersion));
  EXPECT_EQ(QueryColumn(path, "PRAGMA journal_mode")[0], "wal");
  // A store that is there already, even an empty file, is not this call's.
  OpenArtifactStore(path)->WriteArtifact(MakeArtifact("m", "clean", "k", "payload"));
  EXPECT_FALSE(CreateNewStoreFile(path));
  EXPECT_EQ(OpenArtifactStore(path, StoreMode::kReadOnly)->ReadHead("m", "clean")->payload,
            "payload");
  const std::string empty = dir.File("empty.db");
  testing::WriteFile(empty, "");
  EXPECT_FALSE(CreateNewStoreFile(empty));
  EXPECT_FALSE(CreateNewStoreFile(dir.File("no-such-dir/s.db")));
  EXPECT_FALSE(CreateNewStoreFile(":memory:"));
}

}  // namespace
}  // namespace areagraph

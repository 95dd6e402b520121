// The write-ahead log left on close for the writers coming next (ag-run's
// runner before its workers), and folded by the last ordinary close.

#include <gtest/gtest.h>
#include <sys/stat.h>

#include <filesystem>
#include <memory>
#include <string>

#include "store/artifact_store.h"
#include "tests/support/raw_sqlite.h"
#include "tests/support/test_support.h"

namespace areagraph {
namespace {

using testing::MakeArtifact;
using testing::TempDir;

// The log's inode, or 0 when there is no log file.
ino_t LogInode(const std::string& store) {
  struct stat info {};
  return stat((store + "-wal").c_str(), &info) == 0 ? info.st_ino : 0;
}

int64_t LogBytes(const std::string& store) {
  std::error_code missing;
  const auto size = std::filesystem::file_size(store + "-wal", missing);
  return missing ? 0 : static_cast<int64_t>(size);
}

// Artifacts in a copy of the .db file without its log.
int64_t ArtifactsInFileAlone(const std::string& store, const TempDir& elsewhere) {
  const std::string copy = elsewhere.File("alone.db");
  std::filesystem::copy_file(store, copy, std::filesystem::copy_options::overwrite_existing);
  // Before the first fold the file may not even hold the schema.
  if (testing::QueryColumn(
          copy, "SELECT count(*) FROM sqlite_master WHERE name = 'artifacts'")[0] == "0") {
    return 0;
  }
  return std::stoll(testing::QueryColumn(copy, "SELECT count(*) FROM artifacts")[0]);
}

TEST(WriteAheadLogTest, LeftLogIsKeptAndTheNextWriterAppendsToIt) {
  TempDir dir;
  const std::string store = dir.File("s.db");
  {
    // A new store's schema is in its file from the start (store_creation_test).
    const std::unique_ptr<ArtifactStore> first = OpenArtifactStore(store);
    first->WriteArtifact(MakeArtifact("m", "import", "k0", "\x0a\x01x"));
    first->LeaveWriteAheadLogOnClose();
  }
  const ino_t left = LogInode(store);
  ASSERT_NE(left, 0u) << "the log was deleted on close";
  EXPECT_GT(LogBytes(store), 0) << "the log was folded on close";
  {
    const std::unique_ptr<ArtifactStore> next = OpenArtifactStore(store);
    next->WriteArtifact(MakeArtifact("m", "import", "k1", "\x0a\x01x"));
    EXPECT_EQ(LogInode(store), left) << "the next writer made a new log";
    next->LeaveWriteAheadLogOnClose();
  }
  TempDir elsewhere;
  EXPECT_EQ(ArtifactsInFileAlone(store, elsewhere), 0) << "the artifacts should be in the log only";
  // Replayed by the next opener, read-only too.
  EXPECT_TRUE(OpenArtifactStore(store, StoreMode::kReadOnly)->ReadArtifact("m", "k1").has_value());
  // An ordinary close folds everything into the file and removes the log.
  OpenArtifactStore(store).reset();
  EXPECT_EQ(LogBytes(store), 0);
  EXPECT_EQ(ArtifactsInFileAlone(store, elsewhere), 2);
}

// Leaving the log is for files only; the in-memory store has none.
TEST(WriteAheadLogTest, MemoryStoreIgnoresIt) {
  const std::unique_ptr<ArtifactStore> memory = OpenArtifactStore(":memory:");
  memory->LeaveWriteAheadLogOnClose();
  memory->WriteArtifact(MakeArtifact("m", "import", "k1", "\x0a\x01x"));
  EXPECT_TRUE(memory->ReadArtifact("m", "k1").has_value());
}

}  // namespace
}  // namespace areagraph

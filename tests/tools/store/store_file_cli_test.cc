// A store is its file plus, while a writer runs, the -wal beside it. After
// any tool that writes a store has finished, the file alone must be the whole
// store: a user who copies only the .db gets every artifact. Backups are
// consistent while a runner writes.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <thread>
#include <vector>

#include "store/artifact_store.h"
#include "tests/support/raw_sqlite.h"
#include "tests/support/test_support.h"

namespace areagraph::testing {
namespace {

const std::vector<std::string> kMaps = {"examples/two_rooms.png", "examples/corridor_rooms.png",
                                        "examples/office_small.png"};

std::vector<std::string> MapPaths() {
  std::vector<std::string> paths;
  for (const std::string& map : kMaps) paths.push_back(SourcePath(map));
  return paths;
}

int64_t LogBytes(const std::string& store) {
  std::error_code missing;
  const auto size = std::filesystem::file_size(store + "-wal", missing);
  return missing ? 0 : static_cast<int64_t>(size);
}

// The number of artifacts, through SQLite only, of the .db copied alone.
std::string ArtifactsInCopyOfFileAlone(const std::string& store, const TempDir& elsewhere) {
  const std::string copy = elsewhere.File("copy.db");
  std::filesystem::copy_file(store, copy, std::filesystem::copy_options::overwrite_existing);
  return QueryColumn(copy, "SELECT count(*) FROM artifacts")[0];
}

void ExpectFileAloneIsTheStore(const std::string& store, const std::string& artifacts) {
  EXPECT_EQ(LogBytes(store), 0) << "the log was left unfolded";
  TempDir elsewhere;
  EXPECT_EQ(ArtifactsInCopyOfFileAlone(store, elsewhere), artifacts);
  EXPECT_TRUE(OpenArtifactStore(elsewhere.File("copy.db"), StoreMode::kReadOnly)
                  ->Verify({"import"})
                  .empty());
}

void RunOk(const std::string& tool, const std::vector<std::string>& args) {
  const CommandResult result = RunTool(tool, args);
  ASSERT_EQ(result.exit_code, 0) << tool << ": " << result.err;
}

// The case: ag-run's workers end without closing their stores.
TEST(StoreFileTest, AfterAgRunTheFileAloneHoldsEveryArtifact) {
  TempDir dir;
  const std::string store = dir.File("s.db");
  std::vector<std::string> args = {"--store", store, "--jobs", "2"};
  for (const std::string& map : MapPaths()) args.push_back(map);
  RunOk("ag-run", args);
  ExpectFileAloneIsTheStore(store, "21");  // 3 maps, 7 stages
}

// One worker writes into the log the runner left when it created the store
// (it no longer folds it before the worker starts); the end still folds.
TEST(StoreFileTest, AfterAgRunWithOneWorkerTheFileAloneHoldsEveryArtifact) {
  TempDir dir;
  const std::string store = dir.File("s.db");
  RunOk("ag-run", {"--store", store, "--jobs", "1", MapPaths()[0]});
  ExpectFileAloneIsTheStore(store, "7");
}

// Every other tool that writes a store, one after another on one store.
TEST(StoreFileTest, EveryWritingToolLeavesTheFileWhole) {
  TempDir dir;
  const std::string store = dir.File("s.db"), two_rooms = MapPaths()[0];
  const std::vector<std::string> map = {"--store", store, "--map", "two_rooms"};
  RunOk("ag-import", {"--store", store, two_rooms});
  ExpectFileAloneIsTheStore(store, "1");
  int artifacts = 1;
  for (const char* stage :
       {"ag-clean", "ag-voronoi", "ag-prune", "ag-cut", "ag-merge", "ag-match"}) {
    RunOk(stage, map);
    ExpectFileAloneIsTheStore(store, std::to_string(++artifacts));
  }
  std::vector<std::string> changed = map;
  changed.insert(changed.end(), {"--set", "merge.min_area_m2=1"});
  RunOk("ag-pipeline", changed);  // a new merge and match
  ExpectFileAloneIsTheStore(store, "9");
  RunOk("ag-store", {"gc", "--store", store});
  ExpectFileAloneIsTheStore(store, "7");
  const std::string merged = dir.File("merged.db");
  RunOk("ag-store", {"merge", merged, store});
  ExpectFileAloneIsTheStore(merged, "7");
  const std::string backup = dir.File("backup.db");
  RunOk("ag-store", {"backup", "--store", store, backup});
  ExpectFileAloneIsTheStore(backup, "7");
}

// A closing writer folds the log even when another connection keeps the
// store open (SQLite itself folds it only when the last connection closes),
// as ag-live and ag-listen do when they stop.
TEST(StoreFileTest, ClosingWriterFoldsTheLogWhileAReaderStaysOpen) {
  TempDir dir;
  const std::string store = dir.File("s.db");
  RunOk("ag-import", {"--store", store, MapPaths()[0]});
  const std::unique_ptr<ArtifactStore> reader = OpenArtifactStore(store, StoreMode::kReadOnly);
  OpenArtifactStore(store)->WriteArtifact(MakeArtifact("other", "import", "k", "\x0a\x01x"));
  EXPECT_EQ(LogBytes(store), 0);
  TempDir elsewhere;
  EXPECT_EQ(ArtifactsInCopyOfFileAlone(store, elsewhere), "2");
}

// A damaged shard names itself and leaves no output file behind.
TEST(StoreFileTest, MergeOfADamagedShardLeavesNoOutput) {
  TempDir dir;
  const std::string good = dir.File("good.db"), bad = dir.File("bad.db");
  const std::string out = dir.File("out.db");
  RunOk("ag-import", {"--store", good, MapPaths()[0]});
  RunOk("ag-import", {"--store", bad, MapPaths()[1]});
  FlipPayloadByte(bad, QueryColumn(bad, "SELECT cache_key FROM artifacts")[0], 10);
  const std::vector<std::string> before = {"bad.db", "good.db"};
  const CommandResult result = RunTool("ag-store", {"merge", out, good, bad});
  EXPECT_EQ(result.exit_code, 1);
  EXPECT_EQ(CountLines(result.err), 1) << result.err;
  EXPECT_EQ(result.err.rfind("ag-store: store '" + bad + "' is damaged: artifact ", 0), 0u)
      << result.err;
  std::vector<std::string> names;  // read-only opens of the inputs may leave their -wal, -shm
  for (const auto& entry : std::filesystem::directory_iterator(dir.path())) {
    const std::string name = entry.path().filename().string();
    if (name != "good.db-wal" && name != "good.db-shm" && name != "bad.db-wal" &&
        name != "bad.db-shm") {
      names.push_back(name);
    }
  }
  std::sort(names.begin(), names.end());
  EXPECT_EQ(names, before) << "an output or a temporary file was left";
}

TEST(StoreFileTest, VerifySeesADamagedIndexPageWithBothChecks) {
  TempDir dir;
  const std::string store = dir.File("s.db");
  std::vector<std::string> args = {"--store", store, "--jobs", "1"};
  for (const std::string& map : MapPaths()) args.push_back(map);
  RunOk("ag-run", args);
  DamageRootPage(store, "artifacts_by_map_and_time", 512);
  for (const std::vector<std::string>& command :
       {std::vector<std::string>{"verify", "--store", store},
        std::vector<std::string>{"verify", "--quick", "--store", store}}) {
    const CommandResult result = RunTool("ag-store", command);
    EXPECT_EQ(result.exit_code, 1) << result.out;
    EXPECT_EQ(result.out.rfind("- - -: SQLite: ", 0), 0u) << result.out;
  }
}

// A backup taken while ag-run writes is one consistent store.
TEST(StoreFileTest, BackupWhileARunnerWritesIsConsistent) {
  TempDir dir;
  const std::string store = dir.File("s.db"), backup = dir.File("backup.db");
  RunOk("ag-import", {"--store", store, MapPaths()[0]});
  std::vector<std::string> args = {"--store", store, "--jobs", "2"};
  for (const std::string& map : MapPaths()) args.push_back(map);
  std::thread runner([&] { RunOk("ag-run", args); });
  std::this_thread::sleep_for(std::chrono::milliseconds(150));
  const CommandResult result = RunTool("ag-store", {"backup", "--store", store, backup});
  runner.join();
  ASSERT_EQ(result.exit_code, 0) << result.err;
  EXPECT_EQ(LogBytes(backup), 0);
  EXPECT_TRUE(OpenArtifactStore(backup, StoreMode::kReadOnly)->Verify({"import"}).empty());
  const int64_t copied = std::stoll(QueryColumn(backup, "SELECT count(*) FROM artifacts")[0]);
  EXPECT_GE(copied, 1);
  EXPECT_LE(copied, static_cast<int64_t>(MapPaths().size()) * 7);  // 7 stages per map
}

TEST(StoreFileTest, BackupNeverReplacesAFile) {
  TempDir dir;
  const std::string store = dir.File("s.db"), backup = dir.File("backup.db");
  RunOk("ag-import", {"--store", store, MapPaths()[0]});
  WriteFile(backup, "my notes");
  const CommandResult result = RunTool("ag-store", {"backup", "--store", store, backup});
  EXPECT_EQ(result.exit_code, 1);
  EXPECT_EQ(result.err, "ag-store: '" + backup + "' already exists; name a new file\n");
  EXPECT_EQ(ReadFile(backup), "my notes");
}

}  // namespace
}  // namespace areagraph::testing

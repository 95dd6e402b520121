// Tools that only read a store: they read one they cannot write (another
// user's store in another user's folder, a read-only mount), and they leave
// no -wal or -shm beside it.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <string>
#include <vector>

#include "store/artifact_store.h"
#include "tests/support/test_support.h"

namespace areagraph::testing {
namespace {

namespace fs = std::filesystem;

bool Exists(const std::string& path) { return fs::exists(fs::symlink_status(path)); }

// Each reading tool, as arguments after the tool's name; `-` keeps the
// outputs off the store's folder.
std::vector<std::vector<std::string>> ReadingTools(const std::string& store) {
  return {
      {"ag-inspect", "--store", store},
      {"ag-inspect", "--store", store, "--map", "two_rooms"},
      {"ag-inspect", "--store", store, "--history", "two_rooms"},
      {"ag-inspect", "--store", store, "--map", "two_rooms", "--stage", "match", "--json"},
      {"ag-export", "--store", store, "--map", "two_rooms", "--format", "json", "--out", "-"},
      {"ag-render", "--store", store, "--map", "two_rooms", "--out", "-"},
      {"ag-store", "verify", "--store", store},
      {"ag-store", "verify", "--store", store, "--quick"},
      {"ag-store", "failures", "--store", store},
  };
}

std::string Shown(const std::vector<std::string>& command) {
  std::string text;
  for (const std::string& word : command) text += word + " ";
  return text;
}

class ReadOnlyStoreCliTest : public ::testing::Test {
 protected:
  void SetUp() override {
    const CommandResult run =
        RunTool("ag-run", {"--store", store_, SourcePath("examples/two_rooms.png")});
    ASSERT_EQ(run.exit_code, 0) << run.err;
    ASSERT_FALSE(Exists(store_ + "-wal"));
    ASSERT_FALSE(Exists(store_ + "-shm"));
  }

  // Runs `command` (a tool and its arguments) through `prefix` (e.g. as
  // another user); the tool must succeed and leave no side file.
  void ExpectReadsWithoutSideFiles(const std::vector<std::string>& prefix) {
    for (const std::vector<std::string>& command : ReadingTools(store_)) {
      std::vector<std::string> argv = prefix;
      argv.push_back(BinDir() + "/" + command[0]);
      argv.insert(argv.end(), command.begin() + 1, command.end());
      const CommandResult result = RunProgram(argv);
      EXPECT_EQ(result.exit_code, 0) << Shown(command) << ": " << result.err;
      EXPECT_FALSE(Exists(store_ + "-wal")) << Shown(command);
      EXPECT_FALSE(Exists(store_ + "-shm")) << Shown(command);
    }
  }

  TempDir dir_;
  const std::string store_ = dir_.File("s.db");
};

// The side files: every reading tool left an empty -wal and a -shm.
TEST_F(ReadOnlyStoreCliTest, ReadingToolsLeaveNoSideFiles) { ExpectReadsWithoutSideFiles({}); }

bool CanSwitchToNobody() {
  return geteuid() == 0 &&
         RunProgram({"setpriv", "--reuid=nobody", "--regid=nogroup", "--clear-groups", "true"})
                 .exit_code == 0;
}

// The shared collection: root's store in root's folder, read by
// another user, failed with "attempt to write a readonly database".
TEST_F(ReadOnlyStoreCliTest, AnotherUserReadsAStoreInAFolderItCannotWrite) {
  if (!CanSwitchToNobody()) GTEST_SKIP() << "needs root and setpriv to run as user nobody";
  ASSERT_EQ(chmod(dir_.path().c_str(), 0755), 0);
  ASSERT_EQ(chmod(store_.c_str(), 0644), 0);
  ExpectReadsWithoutSideFiles({"setpriv", "--reuid=nobody", "--regid=nogroup", "--clear-groups"});
}

// A store on a read-only mount failed with "unable to open database file".
TEST_F(ReadOnlyStoreCliTest, ToolsReadAStoreOnAReadOnlyMount) {
  const std::string folder = dir_.path();
  for (const std::vector<std::string>& command : ReadingTools(store_)) {
    std::string script = "mount --bind '" + folder + "' '" + folder +
                         "' && mount -o remount,ro,bind '" + folder + "' '" + folder +
                         "' || exit 77; exec '" + BinDir() + "/" + command[0] + "'";
    for (size_t i = 1; i < command.size(); ++i) script += " '" + command[i] + "'";
    const CommandResult result = RunProgram({"unshare", "-m", "sh", "-c", script});
    if (result.exit_code == 77) GTEST_SKIP() << "cannot make a read-only mount here (needs root)";
    EXPECT_EQ(result.exit_code, 0) << Shown(command) << ": " << result.err;
  }
  EXPECT_FALSE(Exists(store_ + "-wal"));
  EXPECT_FALSE(Exists(store_ + "-shm"));
}

// Commits in a -wal that a reader cannot use (no -shm, and the folder is not
// writable to make one): reading the file alone would show an older store,
// so the tools say why they cannot read it.
TEST_F(ReadOnlyStoreCliTest, UnreadableLogOfCommitsIsRefusedInOneLine) {
  if (!CanSwitchToNobody()) GTEST_SKIP() << "needs root and setpriv to run as user nobody";
  {
    const std::unique_ptr<ArtifactStore> store = OpenArtifactStore(store_);
    store->LeaveWriteAheadLogOnClose();
    NewArtifact artifact;
    artifact.map_name = "later";
    artifact.stage = "import";
    artifact.cache_key = "k";
    artifact.input_keys = {"file"};
    artifact.proto_type = "areagraph.proto.GridMap";
    store->WriteArtifact(artifact);
  }
  ASSERT_GT(fs::file_size(store_ + "-wal"), 0u);
  fs::remove(store_ + "-shm");
  ASSERT_EQ(chmod(dir_.path().c_str(), 0755), 0);
  const CommandResult result =
      RunProgram({"setpriv", "--reuid=nobody", "--regid=nogroup", "--clear-groups",
                  BinDir() + "/ag-inspect", "--store", store_});
  EXPECT_EQ(result.exit_code, 1) << result.out;
  EXPECT_EQ(CountLines(result.err), 1) << result.err;
  EXPECT_NE(result.err.find("write-ahead log of commits not yet folded"), std::string::npos)
      << result.err;
  // Its owner reads it, and folds the log.
  const CommandResult owner = RunTool("ag-inspect", {"--store", store_});
  EXPECT_EQ(owner.exit_code, 0) << owner.err;
  EXPECT_NE(owner.out.find("later"), std::string::npos) << owner.out;
  EXPECT_FALSE(Exists(store_ + "-wal"));
}

}  // namespace
}  // namespace areagraph::testing

// ag-store (and the failure listings of ag-inspect) run as a user would.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <string>

#include "store/artifact_store.h"
#include "tests/support/raw_sqlite.h"
#include "tests/support/test_support.h"

namespace areagraph::testing {
namespace {

// A walled room of `width` px, as a PNG.
std::string WriteRoomImage(const TempDir& dir, const std::string& name, int width = 60) {
  cv::Mat image(40, width, CV_8UC1, cv::Scalar(0));
  image(cv::Rect(2, 2, width - 4, 36)).setTo(254);
  const std::string path = dir.File(name + ".png");
  cv::imwrite(path, image);
  return path;
}

void Import(const std::string& store, const std::string& image,
            const std::vector<std::string>& more = {}) {
  std::vector<std::string> args = {"--store", store, image};
  args.insert(args.end(), more.begin(), more.end());
  const CommandResult result = RunTool("ag-import", args);
  ASSERT_EQ(result.exit_code, 0) << result.err;
}

void ExpectOneLineError(const CommandResult& result, const std::string& needle, int code = 1) {
  EXPECT_EQ(result.exit_code, code) << result.out << result.err;
  EXPECT_EQ(CountLines(result.err), 1) << result.err;
  EXPECT_NE(result.err.find(needle), std::string::npos) << result.err;
  EXPECT_EQ(result.err.rfind("ag-store: ", 0), 0u) << result.err;
}

TEST(AgStoreCliTest, HelpForEveryCommand) {
  for (const std::vector<std::string>& args :
       std::vector<std::vector<std::string>>{{"--help"},
                                             {"merge", "--help"},
                                             {"gc", "--help"},
                                             {"verify", "--help"},
                                             {"backup", "--help"},
                                             {"failures", "--help"}}) {
    const CommandResult help = RunTool("ag-store", args);
    EXPECT_EQ(help.exit_code, 0) << args[0] << ": " << help.err;
    EXPECT_NE(help.out.find("--help"), std::string::npos) << help.out;
  }
  EXPECT_NE(RunTool("ag-store", {"gc", "--help"}).out.find("--vacuum"), std::string::npos);
  ExpectOneLineError(RunTool("ag-store", {}), "name a command", 2);
  ExpectOneLineError(RunTool("ag-store", {"merge", "out.db"}), "IN", 2);
  ExpectOneLineError(RunTool("ag-store", {"shrink"}), "shrink", 2);
}

TEST(AgStoreCliTest, MergeShardsThenVerifyAndInspect) {
  TempDir dir;
  const std::string a = dir.File("a.db"), b = dir.File("b.db"), out = dir.File("out.db");
  Import(a, WriteRoomImage(dir, "hall"));
  Import(b, WriteRoomImage(dir, "lab", 80));
  const CommandResult merged = RunTool("ag-store", {"merge", out, a, b});
  ASSERT_EQ(merged.exit_code, 0) << merged.err;
  EXPECT_NE(merged.out.find(a + ": added 1 map, 1 artifact ("), std::string::npos) << merged.out;
  EXPECT_NE(merged.out.find(b + ": added 1 map, 1 artifact ("), std::string::npos) << merged.out;
  EXPECT_NE(merged.out.find("merged 2 stores into " + out), std::string::npos) << merged.out;

  const CommandResult maps = RunTool("ag-inspect", {"--store", out});
  ASSERT_EQ(maps.exit_code, 0) << maps.err;
  EXPECT_NE(maps.out.find("hall"), std::string::npos) << maps.out;
  EXPECT_NE(maps.out.find("lab"), std::string::npos) << maps.out;
  EXPECT_EQ(maps.out.find("failed"), std::string::npos) << maps.out;

  const CommandResult verified = RunTool("ag-store", {"verify", "--store", out});
  EXPECT_EQ(verified.exit_code, 0) << verified.out << verified.err;
  EXPECT_EQ(verified.out, "checked 2 artifacts: no problems\n");
  EXPECT_EQ(verified.err, "");  // no progress line when stderr is not a terminal

  const CommandResult again = RunTool("ag-store", {"merge", out, a});
  ASSERT_EQ(again.exit_code, 0) << again.err;
  EXPECT_NE(again.out.find("added 0 maps, 0 artifacts (0 bytes of payload), 0 failures"),
            std::string::npos)
      << again.out;
}

TEST(AgStoreCliTest, MergeRefusesBadInputsBeforeCreatingOut) {
  TempDir dir;
  const std::string a = dir.File("a.db"), out = dir.File("out.db");
  Import(a, WriteRoomImage(dir, "hall"));
  ExpectOneLineError(RunTool("ag-store", {"merge", out, a, dir.File("missing.db")}),
                     "missing.db' does not exist");
  EXPECT_FALSE(std::filesystem::exists(out));
  WriteFile(dir.File("notes.txt"), "not a store\n");
  ExpectOneLineError(RunTool("ag-store", {"merge", out, dir.File("notes.txt")}),
                     "is not an areagraph store");
  EXPECT_FALSE(std::filesystem::exists(out));
  EXPECT_EQ(ReadFile(dir.File("notes.txt")), "not a store\n");
  ExpectOneLineError(RunTool("ag-store", {"merge", a, a}), "into itself");

  const std::string newer = dir.File("newer.db");
  Import(newer, WriteRoomImage(dir, "attic"));
  ExecSql(newer, "PRAGMA user_version = 99");
  ExpectOneLineError(RunTool("ag-store", {"merge", out, newer}), "newer than this build");
  EXPECT_FALSE(std::filesystem::exists(out));
}

TEST(AgStoreCliTest, VerifyReportsCorruptionWithExitOne) {
  TempDir dir;
  const std::string store = dir.File("s.db");
  Import(store, WriteRoomImage(dir, "hall"));
  const std::string key = QueryColumn(store, "SELECT cache_key FROM artifacts")[0];
  // Well-formed bytes that are not what was written (a flipped byte may break
  // the zstd frame instead, which verify reports in other words).
  ExecSql(store, "UPDATE artifacts SET payload_codec = 0, payload = X'0a0178'");
  const CommandResult result = RunTool("ag-store", {"verify", "--store", store});
  EXPECT_EQ(result.exit_code, 1);
  EXPECT_EQ(result.out, "hall import " + key.substr(0, 12) +
                            ": payload digest mismatch (corrupt); recompute it with ag-import "
                            "--force\nchecked 1 artifact: 1 problem\n");
  EXPECT_EQ(result.err, "");
}

TEST(AgStoreCliTest, GcRemovesReplacedArtifactsAndVacuums) {
  TempDir dir;
  const std::string store = dir.File("s.db"), image = WriteRoomImage(dir, "hall");
  Import(store, image);
  Import(store, image, {"--set", "import.resolution_m=0.1"});  // replaces the head
  const CommandResult gc = RunTool("ag-store", {"gc", "--store", store, "--vacuum"});
  ASSERT_EQ(gc.exit_code, 0) << gc.err;
  EXPECT_NE(gc.out.find("removed 1 artifact ("), std::string::npos) << gc.out;
  EXPECT_NE(gc.out.find(" and 0 empty maps\n"), std::string::npos) << gc.out;
  EXPECT_NE(gc.out.find("vacuumed " + store + ": "), std::string::npos) << gc.out;
  EXPECT_EQ(QueryColumn(store, "SELECT count(*) FROM artifacts"), std::vector<std::string>{"1"});
  const CommandResult again = RunTool("ag-store", {"gc", "--store", store});
  EXPECT_EQ(again.out, "nothing to remove: every artifact is reachable from a head\n");
  EXPECT_EQ(RunTool("ag-store", {"verify", "--store", store}).exit_code, 0);
}

TEST(AgStoreCliTest, MissingStoreIsNeverCreated) {
  TempDir dir;
  const std::string missing = dir.File("missing.db");
  for (const char* command : {"gc", "verify", "failures"}) {
    ExpectOneLineError(RunTool("ag-store", {command, "--store", missing}), "does not exist");
  }
  EXPECT_FALSE(std::filesystem::exists(missing));
}

TEST(AgStoreCliTest, FailuresAreListedByAgStoreAndAgInspect) {
  TempDir dir;
  const std::string store = dir.File("s.db");
  Import(store, WriteRoomImage(dir, "hall"));
  {
    std::unique_ptr<ArtifactStore> writer = OpenArtifactStore(store);
    writer->RecordFailure({"hall", "cut", "no room \"found\"", "hall.png", ""});
    writer->RecordFailure({"broken", "import", "cannot decode 'broken.png'", "broken.png", ""});
  }
  const CommandResult table = RunTool("ag-store", {"failures", "--store", store});
  ASSERT_EQ(table.exit_code, 0) << table.err;
  EXPECT_EQ(CountLines(table.out), 3) << table.out;
  EXPECT_NE(table.out.find("broken"), std::string::npos) << table.out;
  EXPECT_NE(table.out.find("cannot decode 'broken.png'"), std::string::npos) << table.out;
  EXPECT_EQ(RunTool("ag-inspect", {"--store", store, "--failures"}).out, table.out);

  const CommandResult json = RunTool("ag-store", {"failures", "--store", store, "--json"});
  ASSERT_EQ(json.exit_code, 0) << json.err;
  EXPECT_NE(json.out.find("\"message\": \"no room \\\"found\\\"\""), std::string::npos) << json.out;
  EXPECT_NE(json.out.find("\"map\": \"broken\""), std::string::npos) << json.out;

  const CommandResult maps = RunTool("ag-inspect", {"--store", store});
  ASSERT_EQ(maps.exit_code, 0) << maps.err;
  EXPECT_NE(maps.out.find("2 maps failed"), std::string::npos) << maps.out;
  EXPECT_NE(maps.out.find("broken"), std::string::npos) << maps.out;
  EXPECT_NE(maps.out.find("failed in cut"), std::string::npos) << maps.out;

  const CommandResult hall = RunTool("ag-inspect", {"--store", store, "--map", "hall"});
  ASSERT_EQ(hall.exit_code, 0) << hall.err;
  EXPECT_NE(hall.out.find("import"), std::string::npos) << hall.out;
  EXPECT_NE(hall.out.find("failed in cut at "), std::string::npos) << hall.out;
  const CommandResult broken = RunTool("ag-inspect", {"--store", store, "--map", "broken"});
  ASSERT_EQ(broken.exit_code, 0) << broken.err;
  EXPECT_NE(broken.out.find("has no artifacts; it failed in import"), std::string::npos)
      << broken.out;

  const CommandResult misuse =
      RunTool("ag-inspect", {"--store", store, "--failures", "--map", "x"});
  EXPECT_EQ(misuse.exit_code, 1);
  EXPECT_EQ(CountLines(misuse.err), 1) << misuse.err;

  // Without failures, the listings stay as they were.
  OpenArtifactStore(store)->ClearFailure("hall");
  OpenArtifactStore(store)->ClearFailure("broken");
  EXPECT_EQ(RunTool("ag-store", {"failures", "--store", store}).out, "no failures recorded\n");
  EXPECT_EQ(RunTool("ag-inspect", {"--store", store}).out.find("failed"), std::string::npos);
}

// The hidden temporary of a backup or merge, as named by a process `pid` of
// this host (tools/store/new_store_file.h).
std::string TemporaryOf(const std::string& out, pid_t pid) {
  char host[256] = {};
  gethostname(host, sizeof(host) - 1);
  std::string name = host;
  for (char& c : name) {
    if (c == '.' || c == '/') c = '_';
  }
  const std::filesystem::path path(out);
  return (path.parent_path() /
          ("." + path.filename().string() + "." + name + "." + std::to_string(pid) + ".tmp"))
      .string();
}

pid_t DeadProcessId() {
  const pid_t child = fork();
  if (child == 0) _exit(0);
  waitpid(child, nullptr, 0);
  return child;
}

// The leftovers: a killed backup or merge left its hidden temporary
// (95 MB there), which later runs never removed. A later run for the same
// output removes those whose process is gone, and leaves a running one's.
TEST(AgStoreCliTest, BackupAndMergeRemoveTemporariesOfKilledRuns) {
  TempDir dir;
  const std::string store = dir.File("s.db");
  Import(store, WriteRoomImage(dir, "room"));
  for (const std::string& command : {"backup", "merge"}) {
    const std::string out = dir.File(command + ".db");
    const std::string killed = TemporaryOf(out, DeadProcessId());
    const std::string running = TemporaryOf(out, getpid());
    for (const std::string& file : {killed, killed + "-wal", killed + "-shm", running}) {
      WriteFile(file, "left behind");
    }
    const CommandResult result = command == "backup"
                                     ? RunTool("ag-store", {"backup", "--store", store, out})
                                     : RunTool("ag-store", {"merge", out, store});
    EXPECT_EQ(result.exit_code, 0) << result.err;
    for (const std::string& file : {killed, killed + "-wal", killed + "-shm"}) {
      EXPECT_FALSE(std::filesystem::exists(file)) << command << ": " << file;
    }
    EXPECT_TRUE(std::filesystem::exists(running)) << command;
    EXPECT_TRUE(std::filesystem::exists(out)) << command;
  }
}

}  // namespace
}  // namespace areagraph::testing

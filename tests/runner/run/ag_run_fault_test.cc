// ag-run under faults: bad files, crashing workers, a read-only store, a
// runner killed mid-collection, and two runners sharing one store.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>

#include "store/artifact_store.h"
#include "tests/runner/run/runner_test_support.h"
#include "tests/support/raw_sqlite.h"

namespace areagraph::testing {
namespace {

class AgRunFaultTest : public ::testing::Test {
 protected:
  void SetUp() override { std::filesystem::create_directory(maps_); }

  TempDir dir_;
  const std::string maps_ = dir_.File("maps");
  const std::string store_ = dir_.File("s.db");
};

// Verify's problems in a store (none means every payload is intact).
size_t StoreProblems(const std::string& store_path) {
  return OpenArtifactStore(store_path, StoreMode::kReadOnly)->Verify({"import"}).size();
}

TEST_F(AgRunFaultTest, BadFileFailsAloneAndIsRecorded) {
  WriteRandomMaps(maps_, 2, /*first_seed=*/1);
  WriteFile(maps_ + "/broken.png", "\x89PNG\r\n\x1a\n but then nothing an image needs");
  CommandResult run;
  const proto::RunSummary summary = RunJson({"--store", store_, maps_}, &run);
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_EQ(summary.succeeded(), 2);
  EXPECT_EQ(summary.failed(), 1);
  ASSERT_EQ(summary.failures_size(), 1);
  EXPECT_EQ(summary.failures(0).map(), "broken");
  EXPECT_EQ(summary.failures(0).stage(), "import");

  const CommandResult inspect = RunTool("ag-inspect", {"--store", store_, "--failures"});
  EXPECT_EQ(inspect.exit_code, 0);
  EXPECT_NE(inspect.out.find("broken"), std::string::npos) << inspect.out;
  EXPECT_NE(inspect.out.find("import"), std::string::npos) << inspect.out;

  // Once the file is fixed, the next run clears the failure.
  std::filesystem::remove(maps_ + "/broken.png");
  WriteRandomMaps(dir_.path(), 1, /*first_seed=*/7);
  std::filesystem::rename(dir_.File("map_7.png"), maps_ + "/broken.png");
  EXPECT_EQ(RunTool("ag-run", {"--store", store_, maps_}).exit_code, 0);
  EXPECT_TRUE(OpenArtifactStore(store_, StoreMode::kReadOnly)->ReadFailures().empty());
}

TEST_F(AgRunFaultTest, CrashingWorkerFailsItsMapOnly) {
  WriteRandomMaps(maps_, 3, /*first_seed=*/1);
  const std::string command = "AG_RUN_FAULT=crash:map_2:prune exec '" + std::string(AG_BIN_DIR) +
                              "/ag-run' --json --jobs 2 --store '" + store_ + "' '" + maps_ + "'";
  const CommandResult run = RunProgram({"sh", "-c", command});
  EXPECT_EQ(run.exit_code, 1) << run.err;
  EXPECT_NE(run.out.find("\"succeeded\": 2"), std::string::npos) << run.out;
  const auto failures = OpenArtifactStore(store_, StoreMode::kReadOnly)->ReadFailures();
  ASSERT_EQ(failures.size(), 1u);
  EXPECT_EQ(failures[0].map_name, "map_2");
  EXPECT_EQ(failures[0].stage, "prune");
  EXPECT_NE(failures[0].message.find("signal 11"), std::string::npos) << failures[0].message;
  for (const auto& [name, digest] : GraphDigests(store_)) {
    EXPECT_EQ(digest.empty(), name == "map_2") << name;
  }
}

// No worker is left to fold the log when the last map crashes its worker:
// the runner then folds it as it records the failure.
TEST_F(AgRunFaultTest, CrashOnTheLastMapStillLeavesEverythingInTheStoreFile) {
  WriteRandomMaps(maps_, 3, /*first_seed=*/1);  // run in name order: map_3 last
  const std::string command = "AG_RUN_FAULT=crash:map_3:cut exec '" + std::string(AG_BIN_DIR) +
                              "/ag-run' --jobs 1 --store '" + store_ + "' '" + maps_ + "'";
  const CommandResult run = RunProgram({"sh", "-c", command});
  EXPECT_EQ(run.exit_code, 1) << run.err;
  EXPECT_FALSE(HasWriteAheadLog(store_));
  const std::vector<std::string> heads = HeadDigests(store_);
  EXPECT_EQ(heads.size(), 2u * 7u + 4u);  // map_3 up to prune
  EXPECT_EQ(HeadDigestsOfFileAlone(store_), heads);
  const auto failures = OpenArtifactStore(store_, StoreMode::kReadOnly)->ReadFailures();
  ASSERT_EQ(failures.size(), 1u);
  EXPECT_EQ(failures[0].map_name, "map_3");
}

TEST_F(AgRunFaultTest, StoreOnReadOnlyFileSystemIsOneLineError) {
  WriteRandomMaps(maps_, 1, /*first_seed=*/1);
  std::filesystem::create_directory(dir_.File("ro"));
  const std::string store = dir_.File("ro/s.db");
  const std::string script = "mount --bind -o ro '" + dir_.File("ro") + "' '" + dir_.File("ro") +
                             "' || exit 77; exec '" + std::string(AG_BIN_DIR) +
                             "/ag-run' --store '" + store + "' '" + maps_ + "'";
  const CommandResult run = RunProgram({"unshare", "-m", "sh", "-c", script});
  if (run.exit_code == 77) GTEST_SKIP() << "cannot make a read-only mount here";
  EXPECT_NE(run.exit_code, 0);
  EXPECT_EQ(CountLines(run.err), 1) << run.err;
  EXPECT_NE(run.err.find("s.db"), std::string::npos) << run.err;
  EXPECT_FALSE(std::filesystem::exists(store));
}

TEST_F(AgRunFaultTest, KilledRunnerLosesNothingAndTheNextRunFinishes) {
  constexpr int kMaps = 16;
  WriteRandomMaps(maps_, kMaps, /*first_seed=*/100);
  // Start ag-run, wait until a few maps are done, then SIGKILL it mid-collection.
  const std::string script = "'" + std::string(AG_BIN_DIR) + "/ag-run' --jobs 2 --store '" +
                             store_ + "' '" + maps_ +
                             "' >/dev/null 2>&1 & pid=$!; "
                             "for i in $(seq 600); do "
                             "  n=$(sqlite3 '" +
                             store_ +
                             "' \"SELECT count(*) FROM heads WHERE stage='merge'\" "
                             "2>/dev/null || echo 0); "
                             "  [ \"${n:-0}\" -ge 3 ] && break; sleep 0.02; done; "
                             "kill -9 $pid; wait $pid; "
                             "sleep 0.5; sqlite3 '" +
                             store_ +
                             "' \"SELECT (SELECT count(*) FROM heads WHERE stage='merge'), "
                             "(SELECT count(*) FROM heads WHERE stage='match')\"";
  const CommandResult killed = RunProgram({"sh", "-c", script});
  // Merge heads, and heads of the last stage: the kill can fall between the two.
  int done_before = 0;
  int finished_before = 0;
  ASSERT_EQ(std::sscanf(killed.out.c_str(), "%d|%d", &done_before, &finished_before), 2)
      << killed.out << killed.err;
  ASSERT_GE(done_before, 3) << killed.out << killed.err;
  ASSERT_LT(done_before, kMaps) << "the run finished before the kill; the test proves nothing";
  // The workers died with the runner: no head appears after the kill.
  sleep(1);
  EXPECT_EQ(GraphDigests(store_).size() >= static_cast<size_t>(done_before), true);
  int heads_now = 0;
  for (const auto& [name, digest] : GraphDigests(store_)) heads_now += digest.empty() ? 0 : 1;
  EXPECT_EQ(heads_now, done_before);
  EXPECT_EQ(StoreProblems(store_), 0u);

  CommandResult run;
  const proto::RunSummary summary = RunJson({"--store", store_, maps_}, &run);
  EXPECT_EQ(run.exit_code, 0) << run.err;
  EXPECT_EQ(summary.succeeded(), kMaps);
  EXPECT_GE(summary.fully_cached(), finished_before);
  // At most one map per worker (--jobs 2) was between its merge and match.
  EXPECT_GE(finished_before, done_before - 2);
  EXPECT_EQ(StoreProblems(store_), 0u);
}

TEST_F(AgRunFaultTest, TwoRunnersShareOneStore) {
  WriteRandomMaps(maps_, 6, /*first_seed=*/200);
  const std::string run = "'" + std::string(AG_BIN_DIR) + "/ag-run' --jobs 2 --store '" + store_ +
                          "' '" + maps_ + "' >/dev/null 2>&1";
  const CommandResult both = RunProgram({"sh", "-c",
                                         run + " & a=$!; " + run +
                                             " & b=$!; wait $a; ra=$?; wait $b; rb=$?; "
                                             "echo $ra $rb"});
  EXPECT_EQ(both.out, "0 0\n") << both.err;
  EXPECT_EQ(StoreProblems(store_), 0u);
  const auto digests = GraphDigests(store_);
  ASSERT_EQ(digests.size(), 6u);
  for (const auto& [name, digest] : digests) EXPECT_FALSE(digest.empty()) << name;
  EXPECT_EQ(RunJson({"--store", store_, maps_}).cache_misses(), 0);
}

}  // namespace
}  // namespace areagraph::testing

// ag-run stopped by SIGINT or SIGTERM: one line says so, the store's log is
// folded into its file, and the same command finishes the rest.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <string>

#include "store/artifact_store.h"
#include "tests/runner/run/runner_test_support.h"
#include "tests/support/raw_sqlite.h"

namespace areagraph::testing {
namespace {

constexpr int kMaps = 16;

class AgRunInterruptTest : public ::testing::TestWithParam<std::string> {
 protected:
  void SetUp() override {
    std::filesystem::create_directory(maps_);
    WriteRandomMaps(maps_, kMaps, /*first_seed=*/300);
  }

  TempDir dir_;
  const std::string maps_ = dir_.File("maps");
  const std::string store_ = dir_.File("s.db");
  const std::string err_ = dir_.File("err.txt");
};

// The case: the run ended with no word and the -wal beside the store.
TEST_P(AgRunInterruptTest, StopsWithOneLineAndFoldsTheLog) {
  const std::string& signal = GetParam();
  // Started in the background with its stderr in a file (and SIGINT not
  // ignored, as sh would for a background job); signalled once a map is done.
  const std::string script =
      "env --default-signal=INT,TERM '" + BinDir() + "/ag-run' --jobs 2 --store '" + store_ +
      "' '" + maps_ + "' >/dev/null 2>'" + err_ +
      "' & pid=$!; "
      "for i in $(seq 1500); do "
      "  n=$(sqlite3 '" +
      store_ +
      "' \"SELECT count(*) FROM heads WHERE stage='match'\" 2>/dev/null || echo 0); "
      "  [ \"${n:-0}\" -ge 1 ] && break; sleep 0.02; done; "
      "kill -" +
      signal + " $pid; wait $pid; echo $?";
  const CommandResult stopped = RunProgram({"sh", "-c", script});
  const std::string err = ReadFile(err_);
  EXPECT_EQ(stopped.out, "1\n") << err;
  // The last line of stderr (the others are the maps done before) says why.
  const size_t last = err.rfind('\n', err.size() - 2);
  const std::string line = err.substr(last == std::string::npos ? 0 : last + 1);
  EXPECT_EQ(line.rfind("ag-run: stopped by SIG" + signal + " after ", 0), 0u) << err;
  EXPECT_NE(line.find(" of 16 maps; every map that finished is in the store"), std::string::npos)
      << err;
  int done = 0;
  ASSERT_EQ(std::sscanf(line.c_str() + line.find(" after ") + 7, "%d", &done), 1) << line;
  ASSERT_LT(done, kMaps) << "the run finished before the signal; the test proves nothing";

  std::error_code missing;
  const auto log_bytes = std::filesystem::file_size(store_ + "-wal", missing);
  EXPECT_TRUE(missing || log_bytes == 0) << "the log was left unfolded";
  EXPECT_TRUE(OpenArtifactStore(store_, StoreMode::kReadOnly)->Verify({"import"}).empty());
  EXPECT_TRUE(OpenArtifactStore(store_, StoreMode::kReadOnly)->ReadFailures().empty())
      << "maps stopped by the signal are not failures";

  CommandResult run;
  const proto::RunSummary summary = RunJson({"--store", store_, maps_}, &run);
  EXPECT_EQ(run.exit_code, 0) << run.err;
  EXPECT_EQ(summary.succeeded(), kMaps);
}

INSTANTIATE_TEST_SUITE_P(Signals, AgRunInterruptTest, ::testing::Values("TERM", "INT"));

}  // namespace
}  // namespace areagraph::testing

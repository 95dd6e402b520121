// A full disk on the store's side, on a small tmpfs in a mount namespace of
// its own: the tools say "no space left on device", and a writer whose log
// cannot be folded into the file says that the -wal is part of the store.
#include <gtest/gtest.h>

#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "tests/support/test_support.h"

namespace areagraph::testing {
namespace {

// Runs `body` (sh) with a tmpfs of `size` mounted on `disk`; returns its
// output, or skips where no tmpfs can be mounted.
CommandResult OnSmallDisk(const std::string& disk, const std::string& size,
                          const std::string& body) {
  return RunProgram(
      {"unshare", "-m", "sh", "-c",
       "mount -t tmpfs -o size=" + size + " tmpfs '" + disk + "' || exit 77; " + body});
}

class FullDiskStoreCliTest : public ::testing::Test {
 protected:
  void SetUp() override {
    const CommandResult import =
        RunTool("ag-import", {"--store", store_, SourcePath("examples/office_small.png")});
    ASSERT_EQ(import.exit_code, 0) << import.err;
    std::filesystem::create_directory(disk_);
  }

  // Shell lines that put a fresh copy of the store on the disk and fill the
  // disk up to `free_kib` KiB.
  std::string FreshStoreWithFree(const std::string& free_kib) const {
    return "rm -f '" + disk_ + "'/*; cp '" + store_ + "' '" + disk_ +
           "/s.db'; dd if=/dev/zero of='" + disk_ + "/fill' bs=4k 2>/dev/null; truncate -s -" +
           free_kib + "k '" + disk_ + "/fill'; ";
  }

  std::string Tool(const std::string& name) const { return "'" + BinDir() + "/" + name + "'"; }

  TempDir dir_;
  const std::string store_ = dir_.File("s.db");
  const std::string disk_ = dir_.File("disk");
};

// SQLite could not make its -shm and every tool said "disk I/O error".
TEST_F(FullDiskStoreCliTest, IndexThatCannotBeMadeSaysNoSpace) {
  const CommandResult result =
      OnSmallDisk(disk_, "256k",
                  FreshStoreWithFree("0") + Tool("ag-inspect") + " --store '" + disk_ + "/s.db'");
  if (result.exit_code == 77) GTEST_SKIP() << "cannot mount a tmpfs here (needs root)";
  EXPECT_EQ(result.exit_code, 1);
  EXPECT_EQ(result.err, "ag-inspect: store '" + disk_ +
                            "/s.db': no space left on device while reading the schema version\n");
}

// The "after ag-run fills the disk": the log stayed unfolded and the
// .db alone was "malformed", and nothing said so. With room for the log
// but not for the file to grow by it, the fold fails; the tool now says so
// in its one line and exits 1, and once there is room the next tool folds it.
TEST_F(FullDiskStoreCliTest, WriterThatCannotFoldItsLogSaysSo) {
  for (const std::string& command :
       {Tool("ag-pipeline") + " --map office_small --store '" + disk_ + "/s.db'",
        Tool("ag-run") + " --store '" + disk_ + "/s.db' '" +
            SourcePath("examples/office_small.png") + "'"}) {
    // Free space in steps: too little fails a write, enough lets the run
    // end whole; in between the log fits but the file cannot grow by it.
    // Lines other than ag-run's progress ("ag-run: [1/1] ...") are counted.
    std::string body = "for free in $(seq 100 25 1200); do " + FreshStoreWithFree("${free}") +
                       command +
                       " >/dev/null 2>err; rc=$?; "
                       "if grep -q 'could not be folded' err; then "
                       "  echo \"rc=$rc lines=$(grep -vc '^ag-run: \\[' err)\"; tail -1 err; rm '" +
                       disk_ + "/fill'; " + Tool("ag-store") + " verify --store '" + disk_ +
                       "/s.db' >/dev/null; echo \"verify=$? wal=$(stat -c %s '" + disk_ +
                       "/s.db-wal' 2>/dev/null || echo none)\"; exit 0; fi; done; echo never";
    const CommandResult result = OnSmallDisk(disk_, "4m", "cd '" + dir_.path() + "'; " + body);
    if (result.exit_code == 77) GTEST_SKIP() << "cannot mount a tmpfs here (needs root)";
    std::istringstream lines(result.out);
    std::string status, message, after;
    std::getline(lines, status);
    std::getline(lines, message);
    std::getline(lines, after);
    EXPECT_EQ(status, "rc=1 lines=1") << command << "\n" << result.out << result.err;
    EXPECT_NE(message.find("the write-ahead log could not be folded into store '" + disk_ +
                           "/s.db' (no space left on device): '" + disk_ +
                           "/s.db-wal' holds commits that '" + disk_ + "/s.db' alone lacks"),
              std::string::npos)
        << message;
    EXPECT_EQ(after, "verify=0 wal=none") << command;
  }
}

}  // namespace
}  // namespace areagraph::testing

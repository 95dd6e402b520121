// ag-run's second start with glibc's huge-page malloc: when it happens, that
// it happens once, that a user's GLIBC_TUNABLES is left alone, and that glibc
// takes the tunable (through huge-page-malloc-probe, which calls what
// ag-run calls).
#include "runner/run/huge_page_malloc.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <fstream>
#include <string>

#include "tests/support/test_support.h"

namespace areagraph {
namespace {

using testing::CommandResult;
using testing::TempDir;

TEST(HugePageMallocTest, StartsAgainOnlyWhenWantedAndNothingIsSet) {
  int asked = 0;
  const auto yes = [&] { return ++asked, true; };
  EXPECT_EQ(HugePageMallocTunables(nullptr, nullptr, yes), kHugePageMallocTunable);
  EXPECT_EQ(asked, 1);
  EXPECT_FALSE(HugePageMallocTunables(nullptr, nullptr, [] { return false; }));
  // Started again already, or the user's own tunables: no second look at
  // the maps either.
  EXPECT_FALSE(HugePageMallocTunables(nullptr, "1", yes));
  EXPECT_FALSE(HugePageMallocTunables("glibc.malloc.check=0", nullptr, yes));
  EXPECT_FALSE(HugePageMallocTunables("", nullptr, yes));
  EXPECT_EQ(asked, 1);
}

int Starts(const std::string& file) {
  std::ifstream in(file);
  int lines = 0;
  for (std::string line; std::getline(in, line);) ++lines;
  return lines;
}

bool TransparentHugePagesInMadviseMode() {
  std::ifstream in("/sys/kernel/mm/transparent_hugepage/enabled");
  std::string modes;
  std::getline(in, modes);
  return modes.find("[madvise]") != std::string::npos;
}

TEST(HugePageMallocTest, ProgramStartsAgainOnceWithTheTunable) {
  TempDir dir;
  const std::string starts = dir.File("starts");
  const CommandResult run =
      testing::RunProgram({"/usr/bin/env", "-u", "GLIBC_TUNABLES", "-u", kHugePageMallocMarker,
                           testing::BinDir() + "/huge-page-malloc-probe", starts});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_EQ(Starts(starts), 2);
  EXPECT_NE(run.out.find(std::string("tunables=") + kHugePageMallocTunable + "\n"),
            std::string::npos)
      << run.out;
  // glibc advises only in the kernel's "madvise" mode ("always" needs no
  // advice).
  if (TransparentHugePagesInMadviseMode()) {
    EXPECT_NE(run.out.find("advised=1"), std::string::npos) << run.out;
  }
}

TEST(HugePageMallocTest, UsersTunablesAndTheMarkerKeepTheFirstStart) {
  TempDir dir;
  const std::string user = dir.File("user"), marked = dir.File("marked");
  const CommandResult with_user = testing::RunProgram(
      {"/usr/bin/env", "-u", kHugePageMallocMarker, "GLIBC_TUNABLES=glibc.malloc.check=0",
       testing::BinDir() + "/huge-page-malloc-probe", user});
  ASSERT_EQ(with_user.exit_code, 0) << with_user.err;
  EXPECT_EQ(Starts(user), 1);
  EXPECT_NE(with_user.out.find("tunables=glibc.malloc.check=0\n"), std::string::npos)
      << with_user.out;
  EXPECT_NE(with_user.out.find("advised=0"), std::string::npos) << with_user.out;

  const CommandResult with_marker = testing::RunProgram(
      {"/usr/bin/env", "-u", "GLIBC_TUNABLES", std::string(kHugePageMallocMarker) + "=1",
       testing::BinDir() + "/huge-page-malloc-probe", marked});
  ASSERT_EQ(with_marker.exit_code, 0) << with_marker.err;
  EXPECT_EQ(Starts(marked), 1);
  EXPECT_NE(with_marker.out.find("tunables=\n"), std::string::npos) << with_marker.out;
}

// ag-run with a map above 5 Mpx (a PNG header of 3000 x 2000 px and nothing
// after it) starts again and runs on with the same arguments: the map fails
// in its import and is recorded in the store named on the command line.
TEST(HugePageMallocTest, AgRunWithALargeMapRunsOnAfterStartingAgain) {
  TempDir dir;
  std::string png("\x89PNG\r\n\x1a\n\0\0\0\x0dIHDR", 16);
  for (const uint32_t side : {3000u, 2000u}) {
    for (int shift = 24; shift >= 0; shift -= 8) png += static_cast<char>((side >> shift) & 0xff);
  }
  png += std::string("\x08\x00\x00\x00\x00\0\0\0\0", 9);  // 8-bit grey, CRC
  testing::WriteFile(dir.File("large.png"), png);
  const CommandResult run =
      testing::RunProgram({"/usr/bin/env", "-u", "GLIBC_TUNABLES", "-u", kHugePageMallocMarker,
                           testing::BinDir() + "/ag-run", "--jobs", "1", "--store",
                           dir.File("s.db"), dir.File("large.png")});
  EXPECT_EQ(run.exit_code, 1) << run.out << run.err;
  const CommandResult failures =
      testing::RunTool("ag-inspect", {"--store", dir.File("s.db"), "--failures"});
  EXPECT_NE(failures.out.find("large"), std::string::npos) << failures.out << failures.err;
}

}  // namespace
}  // namespace areagraph

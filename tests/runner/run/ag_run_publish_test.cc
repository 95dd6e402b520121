// ag-run --publish reaching ag-listen in another process, inside a private
// network namespace whose loopback carries multicast: nothing leaves it.
#include <gtest/gtest.h>

#include <filesystem>

#include "tests/runner/run/runner_test_support.h"

namespace areagraph::testing {
namespace {

TEST(AgRunPublishTest, NewGraphsArePublishedAndUnchangedOnesAreNot) {
  if (RunProgram({"unshare", "-n", "true"}).exit_code != 0) {
    GTEST_SKIP() << "unshare -n is not permitted here";
  }
  TempDir dir;
  const std::string maps = dir.File("maps"), d = dir.path();
  std::filesystem::create_directory(maps);
  WriteRandomMaps(maps, 2, /*first_seed=*/50);
  const std::string bin = AG_BIN_DIR;
  const std::string run = bin + "/ag-run --json --jobs 2 --publish --store " + d + "/s.db " + maps;
  const std::string script = "ip link set lo up && ip route add 224.0.0.0/4 dev lo || exit 90\n" +
                             bin + "/ag-listen --count 2 --timeout 120 >" + d + "/listen.out 2>" +
                             d +
                             "/listen.err &\n"
                             "L=$!\n"
                             "i=0; until grep -q listening " +
                             d +
                             "/listen.err; do i=$((i+1)); "
                             "[ $i -gt 300 ] && exit 91; sleep 0.1; done\n" +
                             run + " >" + d + "/cold.json || exit 92\n" + run + " >" + d +
                             "/warm.json || exit 93\n"
                             "wait $L || exit 94\n";
  const CommandResult result = RunProgram({"unshare", "-n", "sh", "-c", script});
  ASSERT_EQ(result.exit_code, 0) << result.err << ReadFile(d + "/listen.err");
  EXPECT_NE(ReadFile(d + "/cold.json").find("\"published\": 2"), std::string::npos)
      << ReadFile(d + "/cold.json");
  EXPECT_NE(ReadFile(d + "/warm.json").find("\"published\": 0"), std::string::npos)
      << ReadFile(d + "/warm.json");
  const std::string heard = ReadFile(d + "/listen.out");
  EXPECT_EQ(CountLines(heard), 2) << heard;
  for (const auto& [name, digest] : GraphDigests(d + "/s.db")) {
    EXPECT_NE(heard.find("map " + name + ":"), std::string::npos) << heard;
  }
}

TEST(AgRunPublishTest, UrlThatWouldLeaveTheHostIsRefusedBeforeAnyWork) {
  TempDir dir;
  const CommandResult run =
      RunTool("ag-run", {"--store", dir.File("s.db"), "--publish", "--url",
                         "udpm://239.255.76.67:7667?ttl=1", SourcePath("examples/two_rooms.png")});
  EXPECT_NE(run.exit_code, 0);
  EXPECT_EQ(CountLines(run.err), 1) << run.err;
  EXPECT_NE(run.err.find("ttl"), std::string::npos) << run.err;
  EXPECT_FALSE(std::filesystem::exists(dir.File("s.db")));
}

// --publish takes no value: the maps after it stay maps.
TEST(AgRunPublishTest, PublishIsAFlagAndUrlNeedsIt) {
  TempDir dir;
  CommandResult run = RunTool(
      "ag-run", {"--store", dir.File("s.db"), "--publish", "--url", "memq://", "--jobs", "1",
                 SourcePath("examples/two_rooms.png"), SourcePath("examples/corridor_rooms.png")});
  EXPECT_EQ(run.exit_code, 0) << run.err;
  EXPECT_NE(run.out.find("ag-run: 2 maps"), std::string::npos) << run.out;
  run = RunTool("ag-run", {"--store", dir.File("t.db"), "--url", "memq://",
                           SourcePath("examples/two_rooms.png")});
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find("add --publish"), std::string::npos) << run.err;
  EXPECT_FALSE(std::filesystem::exists(dir.File("t.db")));
}

}  // namespace
}  // namespace areagraph::testing

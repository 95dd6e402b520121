// ag-run's restart with glibc's huge-page tunable: when it applies, what the
// variable becomes, and that a restarted run ends as any other.
#include "runner/run/huge_page_restart.h"

#include <gtest/gtest.h>

#include <fstream>

#include "tests/runner/run/runner_test_support.h"

namespace areagraph {
namespace {

using testing::PngHeaderBytes;
using testing::TempDir;

TEST(HugePageRestartTest, TheTunableIsAddedAfterTheUsersOwn) {
  EXPECT_EQ(WithHugePageTunable(nullptr), "glibc.malloc.hugetlb=1");
  EXPECT_EQ(WithHugePageTunable(""), "glibc.malloc.hugetlb=1");
  EXPECT_EQ(WithHugePageTunable("glibc.malloc.arena_max=2"),
            "glibc.malloc.arena_max=2:glibc.malloc.hugetlb=1");
}

TEST(HugePageRestartTest, AnyHugePageSettingOfTheUserIsKept) {
  EXPECT_FALSE(HasHugePageTunable(nullptr));
  EXPECT_FALSE(HasHugePageTunable("glibc.malloc.arena_max=2"));
  EXPECT_TRUE(HasHugePageTunable("glibc.malloc.hugetlb=0"));  // the user said no
  EXPECT_TRUE(HasHugePageTunable(WithHugePageTunable("glibc.malloc.arena_max=2").c_str()));
}

TEST(HugePageRestartTest, OnlyMapsOverTheWorkersLimitAreBig) {
  const TempDir dir;
  const auto task = [&](const std::string& name, const std::string& bytes) {
    std::ofstream(dir.File(name), std::ios::binary) << bytes;
    MapTask made;
    made.entry.path = dir.File(name);
    return made;
  };
  const MapTask at_limit = task("at_limit.png", PngHeaderBytes(2000, 2500));  // 5.0 Mpx
  const MapTask over = task("over.png", PngHeaderBytes(2000, 2501));
  const MapTask yaml = task("map.yaml", "image: over.png\nresolution: 0.05\n");
  EXPECT_FALSE(HasBigMap({}));
  EXPECT_FALSE(HasBigMap({at_limit, yaml}));
  EXPECT_TRUE(HasBigMap({at_limit, over}));
}

// The restart happens before the store is touched and runs main again: a big
// map that cannot be decoded fails as it would without it, once, with the
// store holding its failure.
TEST(HugePageRestartTest, ARestartedRunEndsAsAnyOther) {
  const TempDir dir;
  std::ofstream(dir.File("big.png"), std::ios::binary) << PngHeaderBytes(3000, 3000);
  testing::CommandResult result;
  const proto::RunSummary summary =
      testing::RunJson({"--store", dir.File("s.db"), "--jobs", "1", dir.File("big.png")}, &result);
  EXPECT_EQ(result.exit_code, 1) << result.err;
  EXPECT_EQ(summary.maps(), 1);
  EXPECT_EQ(summary.failed(), 1);
  const testing::CommandResult failures =
      testing::RunTool("ag-inspect", {"--store", dir.File("s.db"), "--failures"});
  EXPECT_EQ(failures.exit_code, 0) << failures.err;
  EXPECT_NE(failures.out.find("big"), std::string::npos) << failures.out;
}

}  // namespace
}  // namespace areagraph

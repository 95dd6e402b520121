// The value of GLIBC_TUNABLES that a big map's restart sets, and when a
// program may restart at all.
#include "stages/common/huge_page_restart.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <string>

namespace areagraph {
namespace {

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

TEST(HugePageRestartTest, AProcessStartedWithTheTunableDoesNotRestart) {
  const char* given = std::getenv("GLIBC_TUNABLES");
  const std::string before = given == nullptr ? "" : given;
  setenv("GLIBC_TUNABLES", "glibc.malloc.hugetlb=1", 1);
  EXPECT_FALSE(MayRestartWithHugePageTunable());
  unsetenv("GLIBC_TUNABLES");
  EXPECT_TRUE(MayRestartWithHugePageTunable());
  if (given != nullptr) setenv("GLIBC_TUNABLES", before.c_str(), 1);
}

}  // namespace
}  // namespace areagraph

// The value of GLIBC_TUNABLES that a big map's restart sets, when a program
// may restart at all, and how a fresh start knows that it is one.
#include "common/process_setup/huge_page_restart.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <optional>
#include <string>

namespace areagraph {
namespace {

// Sets (or with null unsets) an environment variable for one test and puts
// back what was there.
class ScopedVariable {
 public:
  ScopedVariable(const char* name, const char* value) : name_(name) {
    if (const char* given = std::getenv(name)) before_ = given;
    if (value == nullptr) {
      unsetenv(name);
    } else {
      setenv(name, value, /*overwrite=*/1);
    }
  }
  ~ScopedVariable() {
    if (before_) {
      setenv(name_, before_->c_str(), 1);
    } else {
      unsetenv(name_);
    }
  }

 private:
  const char* name_;
  std::optional<std::string> before_;
};

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
  const ScopedVariable marker(kHugePageRestartVariable, nullptr);
  {
    const ScopedVariable tunables("GLIBC_TUNABLES", "glibc.malloc.hugetlb=1");
    EXPECT_FALSE(MayRestartWithHugePageTunable());
  }
  const ScopedVariable tunables("GLIBC_TUNABLES", nullptr);
  EXPECT_TRUE(MayRestartWithHugePageTunable());
}

TEST(HugePageRestartTest, OnlyTheProgramTheMarkerNamesWasRestarted) {
  const ScopedVariable tunables("GLIBC_TUNABLES", "glibc.malloc.arena_max=8");
  {
    const ScopedVariable marker(kHugePageRestartVariable, "ag-some-other-program");
    EXPECT_FALSE(RestartedWithHugePageTunable());
    EXPECT_EQ(HugePageRestartLine("ag-x"), "");
    EXPECT_TRUE(MayRestartWithHugePageTunable());
  }
  const std::string self = std::filesystem::read_symlink("/proc/self/exe").filename();
  const ScopedVariable marker(kHugePageRestartVariable, self.c_str());
  EXPECT_TRUE(RestartedWithHugePageTunable());
  EXPECT_EQ(HugePageRestartLine("ag-x"), "ag-x: restarted with glibc.malloc.hugetlb=1\n");
  // Even with the tunable gone from its environment, a fresh start does not
  // restart again.
  EXPECT_FALSE(MayRestartWithHugePageTunable());
}

}  // namespace
}  // namespace areagraph

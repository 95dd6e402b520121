// tools/bench-ablation.sh adds the rules beyond the paper one step at a time;
// its last step must be the defaults, so a rule that the defaults turn on
// without a step of its own fails here (the script's --check compares the
// stages' cache keys, which hold the canonical options).
#include <gtest/gtest.h>

#include "tests/support/test_support.h"

namespace areagraph::testing {
namespace {

TEST(AblationSteps, LastStepEqualsTheDefaults) {
  const CommandResult check = RunProgram(
      {"bash", SourcePath("tools/bench-ablation.sh"), "--check", "--build", BinDir() + "/.."});
  EXPECT_EQ(check.exit_code, 0) << check.err;
  EXPECT_NE(check.out.find("equals the defaults"), std::string::npos) << check.out;
}

}  // namespace
}  // namespace areagraph::testing

// tools/bench-ablation.sh turns off, one at a time, the passes of clean,
// cut, merge and match that examples/options/paper.pbtxt skips; its --check
// runs ag-run with each of them, so a pass the options do not know fails
// here, and the count must be every pass there is (cut_passes_test and
// merge_passes_test tie paper.pbtxt to the tables).
#include <gtest/gtest.h>

#include "proto/pipeline_options.pb.h"
#include "tests/support/test_support.h"

namespace areagraph::testing {
namespace {

TEST(AblationPasses, EveryPassIsTurnedOffInTurn) {
  const CommandResult check = RunProgram(
      {"bash", SourcePath("tools/bench-ablation.sh"), "--check", "--build", BinDir() + "/.."});
  EXPECT_EQ(check.exit_code, 0) << check.err;
  const int passes = proto::CleanOptions::Pass_descriptor()->value_count() +
                     proto::CutOptions::Pass_descriptor()->value_count() +
                     proto::MergeOptions::Pass_descriptor()->value_count() +
                     proto::MatchOptions::Pass_descriptor()->value_count();
  EXPECT_EQ(check.out, "bench-ablation: " + std::to_string(passes) + " passes\n") << check.err;
}

}  // namespace
}  // namespace areagraph::testing

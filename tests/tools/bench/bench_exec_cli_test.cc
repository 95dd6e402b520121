// ag-bench-exec: runs a command the asked number of times, each its own
// process, and fails with one line when the command does.
#include <gtest/gtest.h>

#include "tests/support/test_support.h"

namespace areagraph::testing {
namespace {

TEST(BenchExecCli, RunsTheCommandEachTimeAsItsOwnProcess) {
  TempDir dir;
  const std::string log = dir.File("runs.txt");
  const CommandResult result =
      RunTool("ag-bench-exec", {"--repeat", "3", "--", "sh", "-c", "echo run >> " + log});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  EXPECT_EQ(ReadFile(log), "run\nrun\nrun\n");
  EXPECT_NE(result.out.find("cpu_ms "), std::string::npos) << result.out;
  EXPECT_NE(result.out.find(" runs 3\n"), std::string::npos) << result.out;
}

TEST(BenchExecCli, AFailingOrMissingCommandIsOneLineAndNonZero) {
  const CommandResult failing = RunTool("ag-bench-exec", {"--repeat", "2", "--", "false"});
  EXPECT_EQ(failing.exit_code, 1);
  EXPECT_EQ(CountLines(failing.err), 1) << failing.err;
  EXPECT_NE(failing.err.find("'false' failed on run 1"), std::string::npos) << failing.err;
  const CommandResult missing = RunTool("ag-bench-exec", {"--", "/nonexistent/ag-no-such-tool"});
  EXPECT_EQ(missing.exit_code, 1);
  EXPECT_EQ(CountLines(missing.err), 1) << missing.err;
  EXPECT_NE(missing.err.find("cannot run '/nonexistent/ag-no-such-tool'"), std::string::npos)
      << missing.err;
}

}  // namespace
}  // namespace areagraph::testing

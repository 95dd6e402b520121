// A room with 1 % of its cells random obstacles gives thousands of tiny
// areas for ag-merge to fold. Folding used to relabel the whole map per fold
// (12 s at 1000 px, minutes at 2000 px): a slow path that looks like a hang.
// Speed itself is measured by tools/bench-tools.sh; this only catches such a
// path again, with a CPU-time limit about 15 times what ag-merge needs now
// (CPU time, so a busy machine does not make it fail).
#include <gtest/gtest.h>

#include <csignal>
#include <string>
#include <vector>

#include "tests/support/test_support.h"
#include "tools/example_maps/random_floor_plan.h"

namespace areagraph::testing {
namespace {

// Runs `tool` with `args` in a shell that limits it to `cpu_s` seconds of CPU.
CommandResult RunWithCpuLimit(int cpu_s, const std::string& tool,
                              const std::vector<std::string>& args) {
  std::string command =
      "ulimit -t " + std::to_string(cpu_s) + "; exec '" + BinDir() + "/" + tool + "'";
  for (const std::string& arg : args) command += " '" + arg + "'";
  return RunProgram({"sh", "-c", command});
}

TEST(ClutterTest, MergeFoldsThousandsOfTinyAreasWithinACpuLimit) {
  TempDir dir;
  floorplan::WritePlanPng(floorplan::ClutteredRoomPlan(1000, 1.0, /*seed=*/1),
                          dir.File("clutter.png"));
  const std::string store = dir.File("s.db");
  ASSERT_EQ(RunTool("ag-import", {"--store", store, dir.File("clutter.png")}).exit_code, 0);
  for (const char* stage : {"ag-clean", "ag-voronoi", "ag-prune", "ag-cut"}) {
    const CommandResult run = RunTool(stage, {"--store", store, "--map", "clutter"});
    ASSERT_EQ(run.exit_code, 0) << stage << ": " << run.err;
  }
  const CommandResult merge =
      RunWithCpuLimit(6, "ag-merge", {"--store", store, "--map", "clutter"});
  EXPECT_EQ(merge.signal, 0) << "ag-merge ran out of its 6 s of CPU";
  ASSERT_EQ(merge.exit_code, 0) << merge.err;
  EXPECT_NE(merge.out.find(" areas, "), std::string::npos) << merge.out;
}

}  // namespace
}  // namespace areagraph::testing

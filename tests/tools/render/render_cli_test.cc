// ag-render end to end: every stage of a cluttered room is drawn, with a
// CPU-time limit. Filling a polygon used to blend a whole canvas (20 s for
// the prune stage of lab_a, 592 s for a 24-megapixel map): the limit is
// about 20 times what a render needs now, in CPU time so that a busy machine
// does not make it fail. Speed itself is measured by tools/bench-tools.sh.
#include <gtest/gtest.h>

#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <string>
#include <vector>

#include "tests/support/test_support.h"
#include "tools/example_maps/random_floor_plan.h"

namespace areagraph::testing {
namespace {

TEST(AgRenderSpeedCli, EveryStageOfAClutteredRoomWithinACpuLimit) {
  TempDir dir;
  floorplan::WritePlanPng(floorplan::ClutteredRoomPlan(500, 1.0, /*seed=*/1),
                          dir.File("clutter.png"));
  const std::string store = dir.File("s.db");
  const CommandResult run =
      RunTool("ag-run", {"--store", store, "--jobs", "1", dir.File("clutter.png")});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  for (const char* stage : {"import", "clean", "voronoi", "prune", "cut", "merge"}) {
    const std::string out = dir.File(std::string(stage) + ".png");
    const CommandResult render =
        RunProgram({"sh", "-c",
                    "ulimit -t 4; exec '" + BinDir() + "/ag-render' --store '" + store +
                        "' --map clutter --stage " + stage + " --out '" + out + "'"});
    EXPECT_EQ(render.signal, 0) << stage << ": ag-render ran out of its 4 s of CPU";
    ASSERT_EQ(render.exit_code, 0) << stage << ": " << render.err;
    const cv::Mat picture = cv::imread(out, cv::IMREAD_COLOR);
    // The default scale keeps the longer side within 1000 px: 2 px per cell here.
    EXPECT_EQ(picture.size(), cv::Size(1000, 1000)) << stage;
  }
}

}  // namespace
}  // namespace areagraph::testing

// The area stages on maps of the shared dataset (skipped without it): the
// Area Graph invariants must hold on real scans too.
#include <gtest/gtest.h>

#include "stages/clean/clean_stage.h"
#include "stages/import/import_stage.h"
#include "tests/support/area_test_support.h"
#include "tests/support/test_support.h"

namespace areagraph::testing {
namespace {

class SharedMapAreasTest : public ::testing::TestWithParam<const char*> {};

TEST_P(SharedMapAreasTest, AreaGraphInvariantsHold) {
  if (!HaveSharedData()) GTEST_SKIP() << "no ../shared/data";
  const std::string path = SharedDataPath(std::string("areagraph/input/") + GetParam());
  const proto::PipelineOptions options;
  const proto::GridMap grid = ImportGridMap(ReadImportSource(path), options.import());
  const proto::CleanedMap map = CleanGridMap(grid, options.clean());
  const AreaStages stages = RunAreaStages(map, options);
  // Courtyards and hollow furniture are free but closed off: no coverage floor.
  ExpectAreaGraphInvariants(stages, map, /*min_coverage=*/0.5);
  EXPECT_GE(stages.areas.areas_size(), 5);
}

INSTANTIATE_TEST_SUITE_P(Maps, SharedMapAreasTest,
                         ::testing::Values("freiburg_building52.png", "Freiburg101_scan.png",
                                           "lab_e.png"));

}  // namespace
}  // namespace areagraph::testing

// Every pass of the merge's pass table on its constructed case
// (tests/support/merge_pass_cases.h): a drawn floor run through the area
// stages with the defaults but for the case's options, once with every pass
// and once with the pass skipped. With the pass the case's areas come out as
// the pass means them to; without it they do not, so every pass shows an
// effect of its own that no other pass makes up for. A pass added to the
// table without a case fails here. OPEN_BORDER_PASSAGES changes no area and
// is tested on its constructed raster (tests/stages/merge/open_borders_test.cc);
// GROWTH_STOPS_AT_NARROW_GAPS decides which cells an area covers, not which
// areas are one (tests/stages/merge/areas_test.cc).
#include "tests/support/merge_pass_cases.h"

#include <gtest/gtest.h>

#include <ostream>
#include <string>

#include "stages/common/skipped_passes.h"
#include "stages/merge/merge_passes.h"
#include "tests/support/area_test_support.h"

namespace areagraph {

// gtest names a parameter by its pass rather than by its bytes.
void PrintTo(const MergePass& row, std::ostream* out) { *out << MergePassName(row.pass); }

namespace testing {
namespace {

// Whether the area at the case's probe is the area at one of its partners
// (false too when no area holds the probe).
bool ProbeJoinsAPartner(const MergePassCase& c, const proto::PipelineOptions& options) {
  const double res = c.floor.resolution_m();
  const proto::CleanedMap map = CleanDrawnMap(c.floor.image(), options.clean(), res);
  const AreaStages stages = RunAreaStages(map, options);
  ExpectAreaGraphInvariants(stages, map, 0.9);
  const int probe = AreaAt(stages.areas, c.probe.x_m, c.probe.y_m, res);
  EXPECT_NE(probe, -1) << "no area at the probe";
  bool joined = false;
  for (const PlanPoint& partner : c.partners) {
    const int area = AreaAt(stages.areas, partner.x_m, partner.y_m, res);
    EXPECT_NE(area, -1) << "no area at a partner";
    joined = joined || (probe != -1 && area == probe);
  }
  return joined;
}

class MergePassCaseTest : public ::testing::TestWithParam<MergePass> {};

TEST_P(MergePassCaseTest, ThePassMakesItsCaseAndNothingElseDoes) {
  const proto::MergeOptions::Pass pass = GetParam().pass;
  const std::optional<MergePassCase> c = CaseOfMergePass(pass);
  ASSERT_TRUE(c.has_value()) << MergePassName(pass) << " has no constructed case";
  SCOPED_TRACE(c->what);
  ASSERT_TRUE(RunsStagePass(c->options.merge(), pass));
  {
    SCOPED_TRACE("with the pass");
    EXPECT_EQ(ProbeJoinsAPartner(*c, c->options), c->joined);
  }
  {
    SCOPED_TRACE("without the pass");
    proto::PipelineOptions without = c->options;
    without.mutable_merge()->add_skip_passes(pass);
    EXPECT_EQ(ProbeJoinsAPartner(*c, without), !c->joined);
  }
}

// The passes that change areas.
std::vector<MergePass> AreaPasses() {
  std::vector<MergePass> passes;
  for (const MergePass& row : MergePassTable()) {
    if (row.join != nullptr || row.keep != nullptr) passes.push_back(row);
  }
  return passes;
}

INSTANTIATE_TEST_SUITE_P(MergePassTable, MergePassCaseTest, ::testing::ValuesIn(AreaPasses()),
                         [](const ::testing::TestParamInfo<MergePass>& info) {
                           return MergePassName(info.param.pass);
                         });

}  // namespace
}  // namespace testing
}  // namespace areagraph

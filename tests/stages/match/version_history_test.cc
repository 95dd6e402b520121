// The match stage in the stage table: how its previous version enters its
// key, when a run is a hit, the history it writes, ag-run's fully-cached path
// and runs of single stages.
#include <gtest/gtest.h>

#include <map>
#include <set>

#include "stages/pipeline/map_pipeline.h"
#include "stages/pipeline/stage.h"
#include "stages/pipeline/stage_versions.h"
#include "tests/stages/match/plan_runs.h"
#include "tools/example_maps/floor_plan.h"

namespace areagraph {
namespace {

using testing::MatchedGraph;
using testing::RunPlan;
using testing::StableIdAt;

// Three rooms off a corridor.
cv::Mat Plan() {
  floorplan::FloorPlan plan(18, 9);
  floorplan::DrawRoom(plan, {1, 5, 16, 2});
  for (int k = 0; k < 3; ++k) {
    floorplan::DrawRoom(plan, {1 + 5.0 * k, 1, 5, 4});
    floorplan::DrawDoor(plan, 3.5 + 5.0 * k, 5, 0.9, floorplan::WallDirection::kHorizontal);
  }
  return plan.image();
}

// "number<-predecessor number" for each version, oldest first.
std::vector<std::string> Chain(ArtifactStore& store, const std::string& map_name) {
  std::map<std::string, int64_t> numbers;
  std::vector<std::string> chain;
  for (const VersionRecord& version : store.ReadVersions(map_name)) {
    numbers[version.cache_key] = version.number;
    chain.push_back(std::to_string(version.number) + "<-" +
                    (version.predecessor_key.empty()
                         ? std::string("none")
                         : std::to_string(numbers.at(version.predecessor_key))));
  }
  return chain;
}

std::vector<int> RoomIds(const proto::AreaGraph& graph) {
  return {StableIdAt(graph, 3.5, 3), StableIdAt(graph, 8.5, 3), StableIdAt(graph, 13.5, 3)};
}

class VersionHistoryTest : public ::testing::Test {
 protected:
  std::unique_ptr<ArtifactStore> store_ = OpenArtifactStore(":memory:");
};

TEST_F(VersionHistoryTest, OtherOptionsMakeANewVersionThatKeepsTheIds) {
  const proto::PipelineOptions defaults;
  RunPlan(*store_, "m", Plan(), defaults);
  std::string first_key;
  const std::vector<int> ids = RoomIds(MatchedGraph(*store_, "m", &first_key));
  ASSERT_EQ(std::set<int>(ids.begin(), ids.end()).size(), 3u);

  proto::PipelineOptions other = defaults;
  other.mutable_merge()->add_skip_passes(proto::MergeOptions::FOLD_OPEN_BAYS);
  other.mutable_cut()->set_room_width_m(1.25);  // a fixed W (0, the default, estimates it)
  RunPlan(*store_, "m", Plan(), other);
  std::string second_key;
  const proto::AreaGraph second = MatchedGraph(*store_, "m", &second_key);
  EXPECT_NE(second_key, first_key);
  EXPECT_EQ(second.version().number(), 2);
  EXPECT_EQ(second.version().predecessor_key(), first_key);
  EXPECT_EQ(RoomIds(second), ids);

  // The same options again: every stage a hit, no new version.
  EXPECT_TRUE(RunPlan(*store_, "m", Plan(), other).fully_cached);
  EXPECT_EQ(Chain(*store_, "m"), (std::vector<std::string>{"1<-none", "2<-1"}));

  // Back to the first options: the merge artifact is a hit, but the graph is
  // matched to the head (version 2), so it is a new version 3, not version 1.
  const MapOutcome back = RunPlan(*store_, "m", Plan(), defaults);
  EXPECT_FALSE(back.fully_cached);
  EXPECT_EQ(back.cache_hits, back.stages_run - 1);
  std::string third_key;
  const proto::AreaGraph third = MatchedGraph(*store_, "m", &third_key);
  EXPECT_NE(third_key, first_key);
  EXPECT_EQ(RoomIds(third), ids);
  EXPECT_EQ(Chain(*store_, "m"), (std::vector<std::string>{"1<-none", "2<-1", "3<-2"}));
}

TEST_F(VersionHistoryTest, NewMatchOptionsMatchTheSameGraphAgainstTheHead) {
  RunPlan(*store_, "m", Plan());
  std::string first_key;
  const std::vector<int> ids = RoomIds(MatchedGraph(*store_, "m", &first_key));
  proto::PipelineOptions options;
  options.mutable_match()->set_min_overlap(0.8);
  const MapOutcome run = RunPlan(*store_, "m", Plan(), options);
  EXPECT_EQ(run.cache_hits, run.stages_run - 1);
  const proto::AreaGraph second = MatchedGraph(*store_, "m");
  EXPECT_EQ(second.version().predecessor_key(), first_key);
  EXPECT_EQ(RoomIds(second), ids);
}

TEST_F(VersionHistoryTest, PlannedKeysFollowTheHistory) {
  RunPlan(*store_, "m", Plan());
  const proto::PipelineOptions options;
  const std::string import_key = *store_->ReadHeadKey("m", "import");
  const auto lookup = [&](const StageDefinition& stage, const std::vector<std::string>& inputs) {
    return PreviousVersionOf(*store_, "m", stage, options, inputs);
  };
  const std::vector<std::string> planned = PlanPipelineKeys(import_key, options, lookup);
  // The head is the result of this run: its key is planned, so ag-run's
  // fully-cached path needs no stage to run.
  EXPECT_EQ(planned.back(), *store_->ReadHeadKey("m", "match"));
  // Without the store, match is planned as a first version: the same here.
  EXPECT_EQ(PlanPipelineKeys(import_key, options).back(), planned.back());

  proto::PipelineOptions other;
  other.mutable_merge()->set_min_area_m2(2);
  RunPlan(*store_, "m", Plan(), other);
  // Now the head is version 2, made from another merge artifact: the first
  // options would make a version 3 on top of it.
  const std::vector<std::string> again = PlanPipelineKeys(import_key, options, lookup);
  EXPECT_NE(again.back(), planned.back());
  EXPECT_FALSE(store_->HasArtifact("m", again.back()));
  EXPECT_EQ(again.end()[-2], planned.end()[-2]);  // merge: still the first one
}

TEST_F(VersionHistoryTest, AMergeRunAloneLeavesTheVersionForTheNextMatch) {
  RunPlan(*store_, "m", Plan());
  std::string first_key;
  MatchedGraph(*store_, "m", &first_key);
  EXPECT_EQ(NewestGraphKey(*store_, "m"), first_key);

  proto::PipelineOptions other;
  other.mutable_merge()->set_min_area_m2(2);
  RunMapPipeline(*store_, "m", other, false, PipelineObserver(), kMergeStage, kMergeStage);
  EXPECT_EQ(*store_->ReadHeadKey("m", "match"), first_key);  // not run
  // The newest graph is the merge head now: the match head was made from another.
  EXPECT_EQ(NewestGraphKey(*store_, "m"), *store_->ReadHeadKey("m", "merge"));

  RunMapPipeline(*store_, "m", other, false, PipelineObserver(), kMatchStage, kMatchStage);
  const proto::AreaGraph second = MatchedGraph(*store_, "m");
  EXPECT_EQ(second.version().number(), 2);
  EXPECT_EQ(second.version().predecessor_key(), first_key);
  EXPECT_EQ(NewestGraphKey(*store_, "m"), *store_->ReadHeadKey("m", "match"));
}

TEST_F(VersionHistoryTest, ForceRecomputesTheSameVersion) {
  RunPlan(*store_, "m", Plan());
  std::string key;
  const proto::AreaGraph first = MatchedGraph(*store_, "m", &key);
  const StageRun run = RunStageOnHeads(*store_, "m", StageOf(kMatchStage), {}, /*force=*/true);
  EXPECT_FALSE(run.cache_hit);
  EXPECT_EQ(run.cache_key, key);
  EXPECT_EQ(MatchedGraph(*store_, "m").SerializeAsString(), first.SerializeAsString());
  EXPECT_EQ(store_->ReadVersions("m").size(), 1u);
}

}  // namespace
}  // namespace areagraph

// In one process the stages hand artifacts on through ArtifactMemo; an input's
// last reader gets it for itself, prune lets go of the Voronoi diagram once
// it has copied its numbers, and cut frees the Topology Graph's edges as it
// cuts them when the graph is its alone (the peak memory of large maps) and
// calls the caller's hook between its big steps.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "stages/cut/cut_graph_builder.h"
#include "stages/import/import_stage.h"
#include "stages/pipeline/artifact_memo.h"
#include "stages/pipeline/map_pipeline.h"
#include "stages/prune/topology_graph_builder.h"
#include "tests/support/test_support.h"

namespace areagraph {
namespace {

// A store holding `example` (two_rooms by default) up to `last` (the Voronoi
// diagram by default).
std::unique_ptr<ArtifactStore> StoreUpToVoronoi(const proto::PipelineOptions& options,
                                                const StageInfo& last = kVoronoiStage,
                                                const char* example = "examples/two_rooms.png") {
  auto store = OpenArtifactStore(":memory:");
  const ImportSource source = ReadImportSource(testing::SourcePath(example));
  RunCachedStage(*store, "m", StageOf(kImportStage), options, ImportInputs(source), [&] {
    return std::make_unique<proto::GridMap>(ImportGridMap(source, options.import()));
  });
  RunMapPipeline(*store, "m", options, false, PipelineObserver{}, kCleanStage, last);
  return store;
}

TEST(ArtifactMemoTest, SharesAnArtifactUntilItsLastReaderTakesIt) {
  ArtifactMemo memo;
  auto artifact = std::make_shared<proto::VoronoiDiagram>();
  const std::weak_ptr<const google::protobuf::Message> watch = artifact;
  memo.Keep("voronoi", "key", std::move(artifact));
  EXPECT_EQ(memo.Acquire("voronoi", "other-key"), nullptr);
  EXPECT_NE(memo.Acquire("voronoi", "key"), nullptr);
  EXPECT_NE(memo.Acquire("voronoi", "key"), nullptr) << "shared, not handed over";
  memo.MarkLastRead("voronoi");
  std::shared_ptr<const google::protobuf::Message> taken = memo.Acquire("voronoi", "key");
  ASSERT_NE(taken, nullptr);
  EXPECT_EQ(memo.Acquire("voronoi", "key"), nullptr);
  EXPECT_FALSE(watch.expired());
  taken.reset();
  EXPECT_TRUE(watch.expired()) << "the last reader was not the only owner";
}

TEST(InputReleaseTest, PruneReleasesTheDiagramAndNeverReadsItAfter) {
  const proto::PipelineOptions options;
  const auto store = StoreUpToVoronoi(options);
  const auto map = ReadHeadArtifact<proto::CleanedMap>(*store, "m", kCleanStage);
  const auto diagram = ReadHeadArtifact<proto::VoronoiDiagram>(*store, "m", kVoronoiStage);
  const std::string expected =
      BuildTopologyGraph(diagram, map, options.prune()).SerializeAsString();

  proto::VoronoiDiagram consumed = diagram;
  std::vector<size_t> released;
  const MessagePtr graph = StageOf(kPruneStage)
                               .compute(
                                   {&consumed, &map},
                                   [&](size_t input) {
                                     released.push_back(input);
                                     consumed.Clear();  // as if freed
                                   },
                                   options);
  EXPECT_EQ(released, std::vector<size_t>{0});
  EXPECT_TRUE(graph->SerializeAsString() == expected)
      << "prune read the diagram after releasing it";
}

int AbsorbedPolygons(const google::protobuf::RepeatedPtrField<proto::GraphEdge>& edges) {
  int count = 0;
  for (const proto::GraphEdge& edge : edges) count += edge.absorbed_size();
  return count;
}

// Handed over, cut moves the edges that stay one piece and every absorbed
// polygon instead of copying them; the Cut Graph must not change.
TEST(InputReleaseTest, CutFreesTheEdgesOfAGraphHandedOverAndLeavesOneThatIsNot) {
  const proto::PipelineOptions options;
  int absorbed_seen = 0;
  for (const char* example : {"examples/two_rooms.png", "examples/office_small.png"}) {
    const auto store = StoreUpToVoronoi(options, kPruneStage, example);
    const auto map = ReadHeadArtifact<proto::CleanedMap>(*store, "m", kCleanStage);
    const auto topology = ReadHeadArtifact<proto::TopologyGraph>(*store, "m", kPruneStage);
    ASSERT_GT(topology.edges_size(), 1);
    const proto::CutGraph expected_graph = BuildCutGraph(topology, map, options.cut());
    const std::string expected = expected_graph.SerializeAsString();
    EXPECT_EQ(AbsorbedPolygons(expected_graph.edges()), AbsorbedPolygons(topology.edges()));
    absorbed_seen += AbsorbedPolygons(topology.edges());

    for (const bool handed_over : {false, true}) {
      auto input = std::make_shared<proto::TopologyGraph>(topology);
      int takes = 0;
      const InputRelease release([](size_t) {},
                                 [&](size_t i) -> std::shared_ptr<google::protobuf::Message> {
                                   ++takes;
                                   EXPECT_EQ(i, 0u);
                                   return handed_over ? input : nullptr;
                                 });
      const MessagePtr cut = StageOf(kCutStage).compute({input.get(), &map}, release, options);
      EXPECT_EQ(takes, 1);
      EXPECT_TRUE(cut->SerializeAsString() == expected)
          << example << ", handed_over = " << handed_over;
      int emptied = 0;
      for (const proto::GraphEdge& edge : input->edges()) emptied += edge.ByteSizeLong() == 0;
      EXPECT_EQ(emptied, handed_over ? topology.edges_size() : 0)
          << example << ", handed_over = " << handed_over;
    }
  }
  EXPECT_GT(absorbed_seen, 0) << "no absorbed polygon to move";
}

TEST(InputReleaseTest, TheLastReaderFreesTheMemosArtifactAndOthersLeaveIt) {
  const proto::PipelineOptions options;
  for (const bool last_read : {false, true}) {
    const auto store = StoreUpToVoronoi(options);
    std::string key;
    auto diagram = std::make_shared<proto::VoronoiDiagram>(
        ReadHeadArtifact<proto::VoronoiDiagram>(*store, "m", kVoronoiStage, &key));
    const std::weak_ptr<const google::protobuf::Message> watch = diagram;
    ArtifactMemo memo;
    memo.Keep(kVoronoiStage.name, key, std::move(diagram));
    if (last_read) memo.MarkLastRead(kVoronoiStage.name);
    const StageRun run = RunStageOnHeads(*store, "m", StageOf(kPruneStage), options, false, &memo);
    EXPECT_FALSE(run.cache_hit);
    EXPECT_EQ(watch.expired(), last_read) << "last_read = " << last_read;
    EXPECT_EQ(memo.Acquire(kVoronoiStage.name, key) == nullptr, last_read);
  }
}

TEST(InputReleaseTest, CutTakesTheMemosGraphOnlyAsItsLastReader) {
  const proto::PipelineOptions options;
  for (const bool last_read : {false, true}) {
    const auto store = StoreUpToVoronoi(options, kPruneStage);
    std::string key;
    const auto topology = ReadHeadArtifact<proto::TopologyGraph>(*store, "m", kPruneStage, &key);
    auto kept = std::make_shared<proto::TopologyGraph>(topology);
    const std::weak_ptr<const google::protobuf::Message> watch = kept;
    ArtifactMemo memo;
    memo.Keep(kPruneStage.name, key, std::move(kept));
    if (last_read) memo.MarkLastRead(kPruneStage.name);
    const StageRun run = RunStageOnHeads(*store, "m", StageOf(kCutStage), options, false, &memo);
    EXPECT_FALSE(run.cache_hit);
    EXPECT_EQ(watch.expired(), last_read) << "last_read = " << last_read;
    if (!last_read) {
      const auto shared = memo.Acquire(kPruneStage.name, key);
      ASSERT_NE(shared, nullptr);
      EXPECT_TRUE(shared->SerializeAsString() == topology.SerializeAsString())
          << "cut changed a graph that others still read";
    }
  }
}

}  // namespace
}  // namespace areagraph

namespace areagraph {
namespace {

// Programs give freed memory back through the hook that computes call
// between their big steps: cut calls it when it starts and after its
// room-width estimate; a cached stage computes nothing and never calls it.
TEST(InputReleaseTest, CutCallsTheHookBetweenItsBigStepsOnlyWhenItComputes) {
  const proto::PipelineOptions options;
  const auto store = StoreUpToVoronoi(options);
  std::string running;
  std::vector<std::string> calls;  // the stage running at each call
  PipelineObserver observer;
  observer.on_start = [&](const StageInfo& stage) { running = stage.name; };
  observer.between_steps = [&] { calls.push_back(running); };
  RunMapPipeline(*store, "m", options, false, observer, kPruneStage, kMatchStage);
  EXPECT_EQ(calls, (std::vector<std::string>{"cut", "cut"}));
  calls.clear();
  RunMapPipeline(*store, "m", options, false, observer, kPruneStage, kMatchStage);
  EXPECT_TRUE(calls.empty());
}

// ag-run reads the final graph's counts from the memo instead of the store:
// the memo must hold the last stage's artifact, equal to the stored bytes,
// and nothing before it.
TEST(ArtifactMemoTest, ThePipelineLeavesItsLastStagesArtifactInTheMemo) {
  const proto::PipelineOptions options;
  for (const StageInfo& last : {kVoronoiStage, kMatchStage}) {
    auto store = OpenArtifactStore(":memory:");
    const ImportSource source = ReadImportSource(testing::SourcePath("examples/two_rooms.png"));
    RunCachedStage(*store, "m", StageOf(kImportStage), options, ImportInputs(source), [&] {
      return std::make_unique<proto::GridMap>(ImportGridMap(source, options.import()));
    });
    ArtifactMemo memo;
    RunMapPipeline(*store, "m", options, false, PipelineObserver{}, kCleanStage, last, &memo);
    const std::optional<std::string> key = store->ReadHeadKey("m", last.name);
    ASSERT_TRUE(key.has_value());
    const auto kept = memo.Acquire(last.name, *key);
    ASSERT_NE(kept, nullptr) << last.name;
    EXPECT_TRUE(kept->SerializeAsString() == store->ReadArtifact("m", *key)->payload) << last.name;
    const std::optional<std::string> clean_key = store->ReadHeadKey("m", kCleanStage.name);
    EXPECT_EQ(memo.Acquire(kCleanStage.name, *clean_key), nullptr) << last.name;
  }
}

}  // namespace
}  // namespace areagraph

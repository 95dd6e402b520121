// Maps and options the area stages must refuse with one clear error.
#include <gtest/gtest.h>

#include <cmath>

#include "common/error.h"
#include "stages/cut/cut_graph_builder.h"
#include "stages/merge/area_graph_builder.h"
#include "stages/pipeline/stage.h"
#include "stages/prune/topology_graph_builder.h"
#include "tests/support/area_test_support.h"
#include "tests/support/test_support.h"
#include "tools/example_maps/floor_plan.h"

namespace areagraph::testing {
namespace {

using floorplan::DrawRoom;
using floorplan::FloorPlan;

proto::CleanedMap OneRoomMap() {
  FloorPlan plan(6, 5);
  DrawRoom(plan, {0.5, 0.5, 5, 4});
  return CleanedMapFromImage(plan.image());
}

// The prune stage alone, on an empty or hand-made diagram.
std::string PruneError(const proto::VoronoiDiagram& diagram, const proto::CleanedMap& map,
                       const proto::PruneOptions& options = {}) {
  return ErrorOf<InputError>([&] { BuildTopologyGraph(diagram, map, options); });
}

// The merge stage alone, on a hand-made cut graph or cleaned map.
std::string MergeInputError(const proto::CutGraph& cut, const proto::CleanedMap& map) {
  return ErrorOf<InputError>([&] { BuildAreaGraph(cut, map, {}); });
}

TEST(AreaStagesBadInputTest, MapWithoutObstacleSitesHasNoTopologyGraph) {
  const std::string error = PruneError(proto::VoronoiDiagram(), OneRoomMap());
  EXPECT_NE(error.find("no Topology Graph: the map has 0 obstacle cells"), std::string::npos)
      << error;
}

TEST(AreaStagesBadInputTest, FreeSpaceThatNoObstacleEnclosesHasNoTopologyGraph) {
  // Free everywhere but one straight wall: nothing is closed off. (Even an
  // L-shaped wall would enclose its corner up to the 3 m alpha radius.)
  cv::Mat image(300, 300, CV_8U, cv::Scalar(254));
  image(cv::Rect(20, 150, 250, 3)).setTo(0);
  const std::string error = ErrorOf<InputError>([&] { RunAreaStages(CleanedMapFromImage(image)); });
  EXPECT_NE(error.find("no Topology Graph"), std::string::npos) << error;
}

TEST(AreaStagesBadInputTest, SingleFreeCellHasNoTopologyGraph) {
  cv::Mat image(20, 20, CV_8U, cv::Scalar(0));
  image.at<uint8_t>(10, 10) = 254;
  const std::string error = ErrorOf<InputError>([&] { RunAreaStages(CleanedMapFromImage(image)); });
  EXPECT_NE(error.find("no Topology Graph: no Voronoi edge"), std::string::npos) << error;
}

TEST(AreaStagesBadInputTest, AllUnknownOrAllWallMapsAreRefused) {
  for (const int grey : {205, 0}) {
    const cv::Mat image(30, 30, CV_8U, cv::Scalar(grey));
    const std::string error =
        ErrorOf<InputError>([&] { RunAreaStages(CleanedMapFromImage(image)); });
    EXPECT_NE(error.find("the map has no free space"), std::string::npos) << error;
  }
}

TEST(AreaStagesBadInputTest, CorruptArtifactsAreInputErrors) {
  const proto::CleanedMap map = OneRoomMap();
  proto::CleanedMap short_map = map;
  short_map.mutable_cells()->resize(10);
  EXPECT_NE(PruneError(proto::VoronoiDiagram(), short_map).find("the map has 10 cells"),
            std::string::npos);

  const AreaStages stages = RunAreaStages(map);
  proto::VoronoiDiagram diagram = stages.diagram;
  diagram.set_edge_source(0, diagram.vertex_x_size() + 5);
  EXPECT_NE(PruneError(diagram, map).find("corrupt"), std::string::npos);
  diagram = stages.diagram;
  diagram.mutable_edge_clearance_px()->RemoveLast();
  EXPECT_NE(PruneError(diagram, map).find("corrupt"), std::string::npos);
  diagram = stages.diagram;
  diagram.mutable_ray_direction_y()->RemoveLast();
  EXPECT_NE(PruneError(diagram, map).find("corrupt"), std::string::npos);

  proto::TopologyGraph topology = stages.topology;
  topology.mutable_edges(0)->mutable_left_sites()->RemoveLast();
  EXPECT_NE(ErrorOf<InputError>([&] { BuildCutGraph(topology, map, {}); }).find("corrupt"),
            std::string::npos);

  proto::CutGraph cut = stages.cut;
  cut.clear_edges();
  EXPECT_NE(MergeInputError(cut, map).find("no Area Graph: the cut graph has no edges"),
            std::string::npos);

  proto::CleanedMap old_clean = map;
  old_clean.clear_robot_width_m();
  EXPECT_NE(MergeInputError(stages.cut, old_clean).find("the CleanedMap holds no robot width"),
            std::string::npos);

  proto::CutGraph old_cut = stages.cut;
  old_cut.clear_island_max_length_m();
  EXPECT_NE(MergeInputError(old_cut, map).find("the CutGraph holds no island length"),
            std::string::npos);
}

TEST(AreaStagesBadInputTest, AbsurdPruneOptionsAreOptionsErrors) {
  const proto::CleanedMap map = OneRoomMap();
  const proto::VoronoiDiagram diagram = RunAreaStages(map).diagram;
  auto error = [&](auto set) {
    proto::PruneOptions options;
    set(&options);
    return ErrorOf<OptionsError>([&] { BuildTopologyGraph(diagram, map, options); });
  };
  EXPECT_NE(error([](auto* o) { o->set_min_clearance_m(-1); }).find("prune.min_clearance_m"),
            std::string::npos);
  EXPECT_NE(error([](auto* o) { o->set_min_clearance_m(1e9); }).find("larger than the whole map"),
            std::string::npos);
  EXPECT_NE(error([](auto* o) {
              o->set_boundary_alpha_radius_m(0);
            }).find("prune.boundary_alpha_radius_m"),
            std::string::npos);
  EXPECT_NE(error([](auto* o) {
              o->set_boundary_alpha_radius_m(NAN);
            }).find("prune.boundary_alpha_radius_m"),
            std::string::npos);
  EXPECT_NE(error([](auto* o) { o->set_dead_end_passes(-2); }).find("prune.dead_end_passes"),
            std::string::npos);
}

TEST(AreaStagesBadInputTest, AbsurdCutAndMergeOptionsAreOptionsErrors) {
  const proto::CleanedMap map = OneRoomMap();
  const AreaStages stages = RunAreaStages(map);
  auto cut_error = [&](auto set) {
    proto::CutOptions options;
    set(&options);
    return ErrorOf<OptionsError>([&] { BuildCutGraph(stages.topology, map, options); });
  };
  EXPECT_NE(cut_error([](auto* o) { o->set_room_width_m(-1); }).find("cut.room_width_m"),
            std::string::npos);
  EXPECT_NE(cut_error([](auto* o) {
              o->mutable_wall_gaps()->set_max_width_m(-1);
            }).find("cut.wall_gaps.max_width_m"),
            std::string::npos);
  EXPECT_NE(cut_error([](auto* o) { o->set_room_width_m(NAN); }).find("cut.room_width_m"),
            std::string::npos);
  EXPECT_NE(cut_error([](auto* o) { o->set_room_width_m(1e6); }).find("wider than the map"),
            std::string::npos);
  EXPECT_NE(cut_error([](auto* o) { o->set_door_width_m(0.9); }).find("set both or neither"),
            std::string::npos);
  EXPECT_NE(cut_error([](auto* o) {
              o->set_door_width_m(0.9);
              o->set_corridor_width_m(-1);
            }).find("cut.corridor_width_m"),
            std::string::npos);
  EXPECT_NE(cut_error([](auto* o) {
              o->set_door_width_m(3);
              o->set_corridor_width_m(0.05);
            }).find("gives no room width"),
            std::string::npos);

  proto::MergeOptions merge;
  merge.set_min_area_m2(-1);
  EXPECT_NE(ErrorOf<OptionsError>([&] {
              BuildAreaGraph(stages.cut, map, merge);
            }).find("merge.min_area_m2"),
            std::string::npos);
}

TEST(AreaStagesBadInputTest, ZeroWidthsFromStoredCanonicalOptionsMeanUnset) {
  // Canonical option text fills door_width_m and corridor_width_m with 0.
  const proto::CleanedMap map = OneRoomMap();
  proto::PipelineOptions options;
  options.mutable_cut()->set_door_width_m(0);
  options.mutable_cut()->set_corridor_width_m(0);
  EXPECT_EQ(RunAreaStages(map, options).areas.areas_size(), 1);
}

// The builders know nothing of the map; running a stage adds which map and
// which stage failed.
TEST(AreaStagesBadInputTest, StageFailuresNameTheMapAndTheStage) {
  const std::unique_ptr<ArtifactStore> store = OpenArtifactStore(":memory:");
  proto::GridMap grid;
  grid.mutable_frame()->set_width_px(30);
  grid.mutable_frame()->set_height_px(30);
  grid.mutable_frame()->set_resolution_m(0.05);
  grid.set_cells(std::string(900, static_cast<char>(proto::CELL_UNKNOWN)));
  StageInputs inputs;
  inputs.digests = {"file digest"};
  RunCachedStage(*store, "void", StageOf(kImportStage), {}, inputs,
                 [&] { return std::make_unique<proto::GridMap>(grid); });

  try {
    RunStageOnHeads(*store, "void", StageOf(kCleanStage), {});
    FAIL() << "cleaning a map without free space succeeded";
  } catch (const MapStepError& error) {
    EXPECT_EQ(error.map_name(), "void");
    EXPECT_EQ(error.step(), "clean");
    EXPECT_EQ(error.cause(), "the map has no free space");
    EXPECT_STREQ(error.what(), "map 'void', clean: the map has no free space");
  }
  try {
    RunStageOnHeads(*store, "void", StageOf(kPruneStage), {});
    FAIL() << "prune ran without a Voronoi diagram";
  } catch (const MapStepError& error) {
    EXPECT_EQ(error.step(), "prune");
    EXPECT_EQ(error.cause(), "no voronoi artifact; run ag-voronoi first");
  }
}

// An artifact written by a newer build, in a format this one does not know,
// is refused instead of misread.
TEST(AreaStagesBadInputTest, ArtifactOfANewerFormatIsRefused) {
  const std::unique_ptr<ArtifactStore> store = OpenArtifactStore(":memory:");
  proto::AreaGraph graph;
  graph.set_format_version(kAreaGraphFormatVersion + 1);
  StageInputs inputs;
  inputs.digests = {"cut key", "clean key"};
  const StageRun run = RunCachedStage(*store, "future", StageOf(kMergeStage), {}, inputs,
                                      [&] { return std::make_unique<proto::AreaGraph>(graph); });
  const std::string expected = "format version " + std::to_string(kAreaGraphFormatVersion + 1) +
                               ", newer than this build's " +
                               std::to_string(kAreaGraphFormatVersion);
  EXPECT_NE(ErrorOf<StoreError>([&] {
              ReadHeadArtifact<proto::AreaGraph>(*store, "future", kMergeStage);
            }).find(expected),
            std::string::npos);
  EXPECT_NE(ErrorOf<StoreError>([&] {
              ReadArtifactAs<proto::AreaGraph>(*store, "future", run.cache_key);
            }).find(expected),
            std::string::npos);
  graph.set_format_version(kAreaGraphFormatVersion);
  EXPECT_NO_THROW(CheckFormatVersion(graph, "current"));
}

}  // namespace
}  // namespace areagraph::testing

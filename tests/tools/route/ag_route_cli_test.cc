// ag-route end to end: routes on a stored graph, as text and JSON, and one
// clear line with a non-zero exit for every kind of bad input.
#include <google/protobuf/util/json_util.h>
#include <gtest/gtest.h>

#include <memory>
#include <string>
#include <vector>

#include "stages/pipeline/stage.h"
#include "store/artifact_store.h"
#include "tests/support/test_support.h"
#include "tests/tools/route/route_test_graphs.h"
#include "tools/route/free_space.h"
#include "tools/route/route_report.pb.h"
#include "tools/route/stored_graph.h"

namespace areagraph {
namespace {

using testing::CountLines;
using testing::RunTool;
using testing::TempDir;

class AgRouteCli : public ::testing::Test {
 protected:
  void SetUp() override {
    std::unique_ptr<ArtifactStore> store = OpenArtifactStore(store_path_);
    StageInputs inputs;
    inputs.digests = {"cut-artifact-digest"};
    RunCachedStage(*store, "house", StageOf(kMergeStage), {}, inputs,
                   [] { return std::make_unique<proto::AreaGraph>(testing::TwoRoomsWithDoor()); });
  }

  testing::CommandResult Route(std::vector<std::string> args) {
    std::vector<std::string> all = {"--store", store_path_};
    all.insert(all.end(), args.begin(), args.end());
    return RunTool("ag-route", all);
  }

  // Expects exit `code` and exactly the line "ag-route: <message>" on stderr.
  void ExpectFailure(const std::vector<std::string>& args, int code, const std::string& message) {
    const testing::CommandResult run = Route(args);
    EXPECT_EQ(run.exit_code, code) << run.err;
    EXPECT_EQ(run.err, "ag-route: " + message + "\n");
    EXPECT_EQ(run.out, "");
  }

  TempDir dir_;
  const std::string store_path_ = dir_.File("areagraph.db");
};

TEST_F(AgRouteCli, PrintsLengthAreasPassagesAndPolyline) {
  const auto run = Route({"--map", "house", "--from", "1,0.5", "--to", "9,0.5"});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_EQ(run.out,
            "map 'house': route from (1.000, 0.500) to (9.000, 0.500): 8.246 m\n"
            "areas: 0 1\npassages: 0\n"
            "polyline: (1.000, 0.500) (5.000, 1.500) (9.000, 0.500)\n");
}

TEST_F(AgRouteCli, JsonIsTheRouteReportMessage) {
  const auto run = Route({"--map", "house", "--from", "1,2", "--to", "9,2", "--json"});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  route::RouteReport report;
  ASSERT_TRUE(google::protobuf::util::JsonStringToMessage(run.out, &report).ok()) << run.out;
  EXPECT_EQ(report.map_name(), "house");
  EXPECT_DOUBLE_EQ(report.length_m(), 8);
  EXPECT_EQ(report.areas_size(), 2);
  EXPECT_EQ(report.passages_size(), 1);
  ASSERT_EQ(report.polyline_size(), 2);
  EXPECT_EQ(report.polyline(1).x(), 9);
}

TEST_F(AgRouteCli, BadInputGetsOneLineAndANonZeroExit) {
  ExpectFailure({"--map", "house", "--from", "1;2", "--to", "9,2"}, 2,
                "--from must be X,Y in metres (map frame), e.g. --from 1.5,-2; got '1;2'");
  ExpectFailure({"--map", "house", "--from", "1,2", "--to", "nan,2"}, 2,
                "--to must be X,Y in metres (map frame), e.g. --to 1.5,-2; got 'nan,2'");
  ExpectFailure({"--map", "nowhere", "--from", "1,2", "--to", "9,2"}, 1,
                "map 'nowhere' is not in the store");
  ExpectFailure({"--map", "house", "--from", "1,2", "--to", "30,2"}, 1,
                "no route: the goal (30, 2) is more than 1 m from every area");
  ExpectFailure({"--map", "house", "--from", "1,2", "--to", "9,2", "--graph-version", "1"}, 1,
                "map 'house' has no Area Graph versions yet; run ag-match (or ag-run) on it");
  const auto missing_flag = Route({"--map", "house", "--from", "1,2"});
  EXPECT_EQ(missing_flag.exit_code, 2);
  EXPECT_EQ(CountLines(missing_flag.err), 1) << missing_flag.err;
  testing::WriteFile(dir_.File("not-a-store.db"), "not SQLite at all, just some text");
  const auto bad_store = RunTool("ag-route", {"--store", dir_.File("not-a-store.db"), "--map",
                                              "house", "--from", "1,2", "--to", "9,2"});
  EXPECT_EQ(bad_store.exit_code, 1);
  EXPECT_EQ(CountLines(bad_store.err), 1) << bad_store.err;
}

TEST_F(AgRouteCli, RoutesOnAMapThatAgRunSegmentedUseStableIds) {
  const auto run = RunTool("ag-run", {"--store", store_path_, "--jobs", "1",
                                      testing::SourcePath("examples/corridor_rooms.png")});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  std::unique_ptr<ArtifactStore> store = OpenArtifactStore(store_path_, StoreMode::kReadOnly);
  const proto::AreaGraph graph = ReadStoredAreaGraph(*store, "corridor_rooms");
  ASSERT_GE(graph.areas_size(), 3);
  const proto::Area& first = graph.areas(0);
  const proto::Area& last = graph.areas(graph.areas_size() - 1);
  auto xy = [](const proto::Point2& point) {
    return std::to_string(point.x()) + "," + std::to_string(point.y());
  };
  const auto route =
      RunTool("ag-route", {"--store", store_path_, "--map", "corridor_rooms", "--from",
                           xy(first.centroid_m()), "--to", xy(last.centroid_m()), "--json"});
  ASSERT_EQ(route.exit_code, 0) << route.err;
  route::RouteReport report;
  ASSERT_TRUE(google::protobuf::util::JsonStringToMessage(route.out, &report).ok());
  // A centroid may lie outside its own area (an L-shaped corridor).
  const FreeSpace space(graph);
  const int start_area = space.AreaAt({first.centroid_m().x(), first.centroid_m().y()});
  const int goal_area = space.AreaAt({last.centroid_m().x(), last.centroid_m().y()});
  ASSERT_GE(start_area, 0);
  ASSERT_GE(goal_area, 0);
  ASSERT_GE(report.areas_size(), 1);
  EXPECT_EQ(report.areas(0), graph.areas(start_area).stable_id());
  EXPECT_EQ(report.areas(report.areas_size() - 1), graph.areas(goal_area).stable_id());
  EXPECT_EQ(report.passages_size(), report.areas_size() - 1);
}

}  // namespace
}  // namespace areagraph

// ag-live's server in process over memq://: the real pipeline on a small
// example map, the cache, and bad input.
#include "runner/live/live_map_server.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <regex>
#include <sstream>

#include "runner/live/area_graph_publisher.h"
#include "runner/live/lcm_conversion.h"
#include "stages/import/import_stage.h"
#include "stages/pipeline/stage.h"
#include "tests/support/test_support.h"
#include "tools/listen/area_graph_listener.h"

namespace areagraph {
namespace {

proto::GridMap ExampleGrid(const std::string& file) {
  return ImportGridMap(ReadImportSource(testing::SourcePath("examples/" + file)),
                       proto::ImportOptions());
}

// A server and a listener sharing one memq:// instance and an in-memory store.
class LiveMapServerTest : public ::testing::Test {
 protected:
  void SendGrid(const std::string& name, const proto::GridMap& grid, int64_t utime = 1) {
    const areagraph_lcm::grid_map_t message = ToLcmGridMap(name, utime, grid);
    publisher_.connection().publish(kGridMapChannel, &message);
  }
  void SendBytes(const std::string& bytes) {
    publisher_.connection().publish(kGridMapChannel, bytes.data(),
                                    static_cast<unsigned>(bytes.size()));
  }
  // Takes what the server published; Serve dispatched it to the listener
  // already when both were queued together, so this only drains.
  void DrainListener() {
    while (listener_.Listen(0)) {
    }
  }

  std::unique_ptr<ArtifactStore> store_ = OpenArtifactStore(":memory:");
  AreaGraphPublisher publisher_{"memq://"};
  std::ostringstream out_, log_, heard_, listener_log_;
  LiveMapServer server_{*store_, publisher_, proto::PipelineOptions(), out_, log_};
  AreaGraphListener listener_{publisher_.connection(), publisher_.url(), nullptr, heard_,
                              listener_log_};
};

TEST_F(LiveMapServerTest, PublishesTheGraphAndASecondIdenticalMapIsCached) {
  const proto::GridMap grid = ExampleGrid("two_rooms.png");
  SendGrid("two_rooms", grid, 1);
  EXPECT_EQ(server_.Serve(1000), 1);
  std::smatch match;
  const std::string first = out_.str();
  ASSERT_TRUE(std::regex_match(
      first, match,
      std::regex("two_rooms: (\\d+) areas, (\\d+) passages, key ([0-9a-f]{12}), version 1, "
                 "computed 7 of 7 stages in \\d+ ms, published \\d+ ms after receipt\n")))
      << first << log_.str();
  std::string graph_key;
  const auto graph =
      ReadHeadArtifact<proto::AreaGraph>(*store_, "two_rooms", kMatchStage, &graph_key);
  EXPECT_GE(graph.areas_size(), 2);
  EXPECT_EQ(match[1].str(), std::to_string(graph.areas_size()));
  EXPECT_EQ(match[3].str(), graph_key.substr(0, 12));
  DrainListener();
  EXPECT_EQ(heard_.str(), "map two_rooms: " + match[1].str() + " areas, " + match[2].str() +
                              " passages, key " + match[3].str() + ", version 1\n");

  const std::string import_key = *store_->ReadHeadKey("two_rooms", "import");
  const size_t artifacts = store_->ReadArtifactSummaries("two_rooms").size();
  EXPECT_EQ(artifacts, 7u);
  SendGrid("two_rooms", grid, 2);  // a new utime, the same grid
  EXPECT_EQ(server_.Serve(1000), 1);
  const std::string second = out_.str().substr(first.size());
  EXPECT_TRUE(
      std::regex_match(second, std::regex("two_rooms: " + match[1].str() + " areas, " +
                                          match[2].str() + " passages, key " + match[3].str() +
                                          ", version 1, cached, published \\d+ ms "
                                          "after receipt\n")))
      << second;
  EXPECT_EQ(store_->ReadArtifactSummaries("two_rooms").size(), artifacts);
  EXPECT_EQ(*store_->ReadHeadKey("two_rooms", "import"), import_key);
  DrainListener();
  EXPECT_EQ(listener_.graphs_received(), 2);
  EXPECT_EQ(log_.str(), "");
}

TEST_F(LiveMapServerTest, StoresTheGridAsTheMapsImportWithItsDigest) {
  const proto::GridMap grid = ExampleGrid("two_rooms.png");
  SendGrid("lab", grid);
  ASSERT_EQ(server_.Serve(1000), 1);
  const auto stored = ReadHeadArtifact<proto::GridMap>(*store_, "lab", kImportStage);
  EXPECT_EQ(stored.cells(), grid.cells());
  EXPECT_EQ(stored.source_path(), "LCM channel MAP");
  EXPECT_EQ(stored.source_digest(), LiveGridDigest(grid));
  EXPECT_EQ(store_->ReadMap("lab")->source_digest, LiveGridDigest(grid));
}

TEST_F(LiveMapServerTest, SkipsMalformedMessagesAndKeepsServing) {
  SendBytes(std::string(100, '\x5a'));
  areagraph_lcm::grid_map_t invalid = ToLcmGridMap("lab", 1, ExampleGrid("two_rooms.png"));
  invalid.cells[0] = 101;
  publisher_.connection().publish(kGridMapChannel, &invalid);
  SendGrid("lab", ExampleGrid("two_rooms.png"));
  EXPECT_EQ(server_.Serve(1000), 1);
  EXPECT_EQ(server_.messages_rejected(), 2);
  EXPECT_EQ(server_.maps_handled(), 1);
  EXPECT_NE(log_.str().find("ag-live: skipped a malformed message on MAP (100 bytes): not a "
                            "message of type grid_map_t"),
            std::string::npos)
      << log_.str();
  EXPECT_NE(log_.str().find("grid_map_t 'lab': cell (0, 0) has value 101"), std::string::npos)
      << log_.str();
  EXPECT_NE(out_.str().find("lab: "), std::string::npos);
  EXPECT_TRUE(store_->ReadHeadKey("lab", "merge").has_value());
}

TEST_F(LiveMapServerTest, AFailingMapIsRecordedAndTheNextOneServed) {
  // Nothing but free space: no walls to build a Voronoi diagram from.
  proto::GridMap empty = ExampleGrid("two_rooms.png");
  empty.set_cells(std::string(empty.cells().size(), static_cast<char>(proto::CELL_FREE)));
  SendGrid("empty", empty);
  EXPECT_EQ(server_.Serve(1000), 1);
  EXPECT_EQ(server_.maps_failed(), 1);
  EXPECT_NE(log_.str().find("ag-live: map 'empty' failed in "), std::string::npos) << log_.str();
  EXPECT_NE(log_.str().find("; still serving"), std::string::npos);
  const auto failures = store_->ReadFailures();
  ASSERT_EQ(failures.size(), 1u);
  EXPECT_EQ(failures[0].map_name, "empty");
  EXPECT_EQ(failures[0].source_path, "LCM channel MAP");
  EXPECT_NE(log_.str().find("failed in " + failures[0].stage + ": " + failures[0].message),
            std::string::npos)
      << log_.str();
  EXPECT_NE(failures[0].stage, "import");
  EXPECT_EQ(out_.str(), "");

  SendGrid("two_rooms", ExampleGrid("two_rooms.png"));
  EXPECT_EQ(server_.Serve(1000), 1);
  EXPECT_NE(out_.str().find("two_rooms: "), std::string::npos);
  EXPECT_EQ(server_.maps_failed(), 1);
}

// A robot's map that grows: the second grid reveals the corridor's far end.
// The room seen in both keeps its id, the graph goes out as version 2 with
// the first as predecessor, and with diffs on, what changed goes out too.
TEST_F(LiveMapServerTest, AGrowingMapKeepsItsIdsAndSendsDiffs) {
  server_.set_publish_diffs(true);
  AreaGraphListener with_diffs{publisher_.connection(), publisher_.url(), nullptr, heard_,
                               listener_log_,           /*diffs=*/true};
  const proto::GridMap whole = ExampleGrid("corridor_rooms.png");
  proto::GridMap part = whole;
  // Unknown beyond the left 60 % of the columns.
  const int width = whole.frame().width_px();
  std::string cells = part.cells();
  for (size_t i = 0; i < cells.size(); ++i) {
    if (static_cast<int>(i % width) >= width * 6 / 10) cells[i] = proto::CELL_UNKNOWN;
  }
  part.set_cells(cells);
  SendGrid("robot", part, 100);
  ASSERT_EQ(server_.Serve(1000), 1);
  std::string first_key;
  const auto first = ReadHeadArtifact<proto::AreaGraph>(*store_, "robot", kMatchStage, &first_key);
  SendGrid("robot", whole, 200);
  ASSERT_EQ(server_.Serve(1000), 1);
  ASSERT_EQ(server_.maps_failed(), 0) << log_.str();
  std::string second_key;
  const auto second =
      ReadHeadArtifact<proto::AreaGraph>(*store_, "robot", kMatchStage, &second_key);
  EXPECT_EQ(second.version().number(), 2);
  EXPECT_EQ(second.version().predecessor_key(), first_key);
  // The areas of the first graph that lie wholly in the part seen first kept their ids.
  const double seen_x = whole.frame().origin_x_m() + 0.6 * width * whole.frame().resolution_m();
  int kept = 0;
  for (const proto::Area& area : first.areas()) {
    double max_x = -1e9;
    for (const proto::Point2& point : area.polygon_m().outer().points()) {
      max_x = std::max(max_x, point.x());
    }
    if (max_x > seen_x - 0.5) continue;  // at the frontier: may grow or split
    bool found = false;
    for (const proto::Area& now : second.areas()) found |= now.stable_id() == area.stable_id();
    EXPECT_TRUE(found) << "area " << area.stable_id();
    ++kept;
  }
  EXPECT_GE(kept, 1);
  DrainListener();
  const std::string heard = heard_.str();
  EXPECT_NE(heard.find("key " + second_key.substr(0, 12) + ", version 2\n"), std::string::npos)
      << heard;
  EXPECT_NE(heard.find("diff robot: version 1 -> 2, areas +"), std::string::npos) << heard;
  EXPECT_EQ(with_diffs.diffs_received(), 1);
  EXPECT_NE(out_.str().find("version 2, computed 7 of 7 stages"), std::string::npos) << out_.str();
  // The same grid again: the same graph again, and no diff.
  SendGrid("robot", whole, 300);
  ASSERT_EQ(server_.Serve(1000), 1);
  DrainListener();
  EXPECT_EQ(with_diffs.diffs_received(), 1);
  EXPECT_EQ(with_diffs.graphs_received(), 3);
}

// A subscriber that starts after version 1 went out, and so never sees it,
// gets version 2 whole: every area and passage with the ids ag-live stored,
// whether or not it also listens to the diffs.
TEST_F(LiveMapServerTest, ASubscriberThatJoinsLateGetsTheWholeGraph) {
  server_.set_publish_diffs(true);
  const proto::GridMap whole = ExampleGrid("corridor_rooms.png");
  proto::GridMap part = whole;
  std::string cells = part.cells();
  const int width = whole.frame().width_px();
  for (size_t i = 0; i < cells.size(); ++i) {
    if (static_cast<int>(i % width) >= width / 2) cells[i] = proto::CELL_UNKNOWN;
  }
  part.set_cells(cells);
  SendGrid("robot", part, 100);
  ASSERT_EQ(server_.Serve(1000), 1);
  DrainListener();

  std::unique_ptr<ArtifactStore> late_store = OpenArtifactStore(":memory:");
  std::ostringstream late_heard, late_log;
  AreaGraphListener late{
      publisher_.connection(), publisher_.url(), late_store.get(), late_heard, late_log,
      /*diffs=*/true};
  SendGrid("robot", whole, 200);
  ASSERT_EQ(server_.Serve(1000), 1);
  DrainListener();
  ASSERT_EQ(late.graphs_received(), 1) << late_log.str();
  EXPECT_EQ(late.diffs_received(), 1);
  const auto made = ReadHeadArtifact<proto::AreaGraph>(*store_, "robot", kMatchStage);
  ASSERT_EQ(made.version().number(), 2);
  EXPECT_GE(made.areas_size(), 2);
  const auto received = ReadHeadArtifact<proto::AreaGraph>(*late_store, "robot", kMergeStage);
  EXPECT_EQ(received.version().number(), 2);
  ASSERT_EQ(received.areas_size(), made.areas_size());
  for (int i = 0; i < made.areas_size(); ++i) {
    EXPECT_EQ(received.areas(i).stable_id(), made.areas(i).stable_id()) << i;
    EXPECT_EQ(received.areas(i).polygon_m().outer().points_size(),
              made.areas(i).polygon_m().outer().points_size())
        << i;
  }
  ASSERT_EQ(received.passages_size(), made.passages_size());
  for (int i = 0; i < made.passages_size(); ++i) {
    EXPECT_EQ(received.passages(i).stable_id(), made.passages(i).stable_id()) << i;
  }
}

TEST_F(LiveMapServerTest, HandlesOnlyTheNewestQueuedGridOfAMap) {
  SendGrid("lab", ExampleGrid("two_rooms.png"), 1);
  const proto::GridMap newer = ExampleGrid("corridor_rooms.png");
  SendGrid("lab", newer, 2);
  EXPECT_EQ(server_.Serve(1000), 1);
  EXPECT_NE(log_.str().find("map 'lab': a newer grid arrived"), std::string::npos) << log_.str();
  const auto stored = ReadHeadArtifact<proto::GridMap>(*store_, "lab", kImportStage);
  EXPECT_EQ(stored.source_digest(), LiveGridDigest(newer));
}

}  // namespace
}  // namespace areagraph

// The LCM URL rule (traffic stays on the host) and publishing / listening
// through memq://, LCM's in-process provider.
#include <gtest/gtest.h>

#include <chrono>
#include <sstream>
#include <vector>

#include "common/error.h"
#include "runner/live/area_graph_publisher.h"
#include "runner/live/lcm_connection.h"
#include "runner/live/lcm_conversion.h"
#include "stages/match/area_graph_diff.h"
#include "stages/pipeline/stage.h"
#include "tests/runner/live/lcm_test_maps.h"
#include "tools/listen/area_graph_listener.h"

namespace areagraph {
namespace {

using testing::ThrowsMessage;

TEST(HostLocalLcmUrl, AddsTtlZeroWhenMissing) {
  EXPECT_EQ(HostLocalLcmUrl("udpm://239.255.76.67:7667"), "udpm://239.255.76.67:7667?ttl=0");
  EXPECT_EQ(HostLocalLcmUrl("udpm://239.255.76.67:7667?recv_buf_size=65536"),
            "udpm://239.255.76.67:7667?recv_buf_size=65536&ttl=0");
  EXPECT_EQ(HostLocalLcmUrl(kDefaultLcmUrl), kDefaultLcmUrl);
  EXPECT_EQ(HostLocalLcmUrl("memq://"), "memq://");
}

TEST(ReceivingLcmUrl, AsksForABigReceiveBufferUnlessGiven) {
  EXPECT_EQ(ReceivingLcmUrl("udpm://239.255.76.67:7667"),
            "udpm://239.255.76.67:7667?ttl=0&recv_buf_size=8388608");
  EXPECT_EQ(ReceivingLcmUrl("udpm://239.255.76.67:7667?recv_buf_size=65536"),
            "udpm://239.255.76.67:7667?recv_buf_size=65536&ttl=0");
  EXPECT_EQ(ReceivingLcmUrl("memq://"), "memq://");
  EXPECT_THROW(ReceivingLcmUrl("udpm://239.255.76.67:7667?ttl=1"), OptionsError);
}

TEST(HostLocalLcmUrl, RefusesUrlsThatLeaveTheHost) {
  EXPECT_TRUE(ThrowsMessage([] { HostLocalLcmUrl("udpm://239.255.76.67:7667?ttl=1"); },
                            "sets ttl=1, which would send traffic beyond this host"));
  EXPECT_TRUE(ThrowsMessage([] { HostLocalLcmUrl("udpm://239.255.76.67:7667?ttl=0&ttl=2"); },
                            "sets ttl=2"));
  EXPECT_TRUE(ThrowsMessage([] { HostLocalLcmUrl("tcpq://10.0.0.1:7700"); },
                            "LCM provider 'tcpq' in 'tcpq://10.0.0.1:7700' is not supported"));
  EXPECT_TRUE(ThrowsMessage([] { HostLocalLcmUrl("239.255.76.67:7667"); }, "has no provider"));
  // The publisher checks before LCM is even created.
  EXPECT_THROW(AreaGraphPublisher("udpm://239.255.76.67:7667?ttl=3"), OptionsError);
}

TEST(AreaGraphPublisher, ListenerReceivesWhatIsPublished) {
  AreaGraphPublisher publisher("memq://");
  std::ostringstream out, log;
  AreaGraphListener listener(publisher.connection(), publisher.url(), nullptr, out, log);
  publisher.Publish("lab", "0123456789abcdef", testing::MakeAreaGraph());
  EXPECT_TRUE(listener.Listen(1000));
  EXPECT_EQ(out.str(), "map lab: 2 areas, 1 passages, key 0123456789ab, version 0\n");
  EXPECT_EQ(listener.graphs_received(), 1);
  EXPECT_EQ(log.str(), "");
  // Nothing else was sent.
  EXPECT_FALSE(listener.Listen(0));
}

// Records the utime, sequence and map_utime of each area_graph_t received.
struct StampRecorder {
  void OnGraph(const lcm::ReceiveBuffer*, const std::string&,
               const areagraph_lcm::area_graph_t* graph) {
    stamps.push_back({graph->utime, graph->sequence, graph->map_utime});
  }
  std::vector<std::vector<int64_t>> stamps;
};

TEST(AreaGraphPublisher, StampsEachGraphWithTimeAndSequence) {
  AreaGraphPublisher publisher("memq://");
  StampRecorder recorder;
  publisher.connection().subscribe(kAreaGraphChannel, &StampRecorder::OnGraph, &recorder);
  const int64_t before = std::chrono::duration_cast<std::chrono::microseconds>(
                             std::chrono::system_clock::now().time_since_epoch())
                             .count();
  publisher.Publish("lab", "k1", testing::MakeAreaGraph(), 1234);
  publisher.Publish("lab", "k2", testing::MakeAreaGraph());
  while (publisher.connection().handleTimeout(0) > 0) {
  }
  ASSERT_EQ(recorder.stamps.size(), 2u);
  EXPECT_GE(recorder.stamps[0][0], before);
  EXPECT_LE(recorder.stamps[0][0], recorder.stamps[1][0]);
  EXPECT_LT(recorder.stamps[1][0] - before, 60 * 1000 * 1000);  // microseconds, not seconds
  EXPECT_EQ(recorder.stamps[0][1], 0);
  EXPECT_EQ(recorder.stamps[1][1], 1);
  EXPECT_EQ(recorder.stamps[0][2], 1234);
  EXPECT_EQ(recorder.stamps[1][2], 0);
}

TEST(AreaGraphListener, PrintsDiffsWhenAskedTo) {
  AreaGraphPublisher publisher("memq://");
  std::ostringstream out, log, plain_out;
  AreaGraphListener listener(publisher.connection(), publisher.url(), nullptr, out, log,
                             /*diffs=*/true);
  AreaGraphListener plain(publisher.connection(), publisher.url(), nullptr, plain_out, log);
  proto::AreaGraph first, second;
  testing::MakeTwoVersions(first, second);
  publisher.PublishDiff("lab", "second-key", DiffAreaGraphs(first, second), second);
  publisher.Publish("lab", "second-key", second);
  while (listener.Listen(100)) {
  }
  EXPECT_EQ(out.str(),
            "diff lab: version 1 -> 2, areas +1 -0 ~1 =1, passages +1 -0 ~0 =1\n"
            "map lab: 3 areas, 2 passages, key second-key, version 2\n");
  EXPECT_EQ(listener.diffs_received(), 1);
  EXPECT_EQ(plain_out.str(), "map lab: 3 areas, 2 passages, key second-key, version 2\n");
  EXPECT_EQ(log.str(), "");
}

TEST(AreaGraphListener, SkipsMalformedMessagesAndKeepsListening) {
  AreaGraphPublisher publisher("memq://");
  std::ostringstream out, log;
  AreaGraphListener listener(publisher.connection(), publisher.url(), nullptr, out, log);
  const std::string garbage = "definitely not an area graph";
  publisher.connection().publish(kAreaGraphChannel, garbage.data(),
                                 static_cast<unsigned>(garbage.size()));
  areagraph_lcm::area_graph_t inconsistent = ToLcmAreaGraph("lab", "k", testing::MakeAreaGraph());
  inconsistent.passages[0].area_b = 42;
  publisher.connection().publish(kAreaGraphChannel, &inconsistent);
  publisher.Publish("lab", "k2", testing::MakeAreaGraph());
  while (listener.Listen(100)) {
  }
  EXPECT_EQ(listener.messages_rejected(), 2);
  EXPECT_EQ(listener.graphs_received(), 1);
  EXPECT_NE(log.str().find("ag-listen: skipped a malformed message on AREA_GRAPH (28 bytes): not a "
                           "message of type area_graph_t (type fingerprint does not match)"),
            std::string::npos)
      << log.str();
  EXPECT_NE(log.str().find("passage 7 joins an area that is not in the graph"), std::string::npos);
  EXPECT_EQ(out.str(), "map lab: 2 areas, 1 passages, key k2, version 0\n");
}

TEST(AreaGraphListener, StoresReceivedGraphsOnceUnderADerivedKey) {
  const std::unique_ptr<ArtifactStore> store = OpenArtifactStore(":memory:");
  AreaGraphPublisher publisher("memq://");
  std::ostringstream out, log;
  AreaGraphListener listener(publisher.connection(), publisher.url(), store.get(), out, log);
  const std::string published_key(64, 'a');
  publisher.Publish("lab", published_key, testing::MakeAreaGraph());
  publisher.Publish("lab", published_key, testing::MakeAreaGraph());
  while (listener.Listen(100)) {
  }
  EXPECT_EQ(out.str(),
            "map lab: 2 areas, 1 passages, key aaaaaaaaaaaa, version 0, stored\n"
            "map lab: 2 areas, 1 passages, key aaaaaaaaaaaa, version 0, already stored\n");

  std::string key;
  const auto graph = ReadHeadArtifact<proto::AreaGraph>(*store, "lab", kMergeStage, &key);
  EXPECT_EQ(key, ReceivedAreaGraphKey(published_key));
  EXPECT_NE(key, published_key);
  EXPECT_EQ(graph.areas_size(), 2);
  EXPECT_EQ(graph.passages(0).id(), 0);
  EXPECT_EQ(graph.passages(0).stable_id(), 7);
  const auto summaries = store->ReadArtifactSummaries("lab");
  ASSERT_EQ(summaries.size(), 1u);
  EXPECT_EQ(summaries[0].stage, "merge");
  EXPECT_TRUE(summaries[0].input_keys.empty());
  EXPECT_NE(summaries[0].options_text.find(published_key), std::string::npos);
  EXPECT_EQ(summaries[0].stage_version, 0);
}

}  // namespace
}  // namespace areagraph

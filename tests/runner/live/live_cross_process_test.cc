// ag-live, ag-listen, the example subscriber and a grid sender as separate
// processes talking over UDP multicast, all inside a private network
// namespace (unshare -n) with multicast routed on its loopback: nothing
// reaches the host's network.
#include <gtest/gtest.h>

#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "proto/artifacts.pb.h"
#include "stages/pipeline/stage.h"
#include "store/artifact_store.h"
#include "tests/support/test_support.h"

namespace areagraph {
namespace {

using testing::ReadFile;
using testing::RunProgram;
using testing::SourcePath;
using testing::TempDir;

// Runs `body` under sh inside a fresh network namespace whose loopback is up
// and carries 224.0.0.0/4. `wait_for FILE TEXT` waits (bounded) for TEXT.
testing::CommandResult RunInPrivateNetwork(const std::string& body) {
  const std::string script =
      "ip link set lo up && ip route add 224.0.0.0/4 dev lo || exit 90\n"
      // Background processes add their pid to PIDS; none outlives a failure.
      "PIDS=''\n"
      "trap 'kill $PIDS 2>/dev/null' EXIT\n"
      "wait_for() {\n"
      "  i=0\n"
      "  until grep -q \"$2\" \"$1\" 2>/dev/null; do\n"
      "    i=$((i+1))\n"
      "    if [ $i -gt 1200 ]; then echo \"no '$2' in $1\" >&2; cat \"$1\" >&2; exit 91; fi\n"
      "    sleep 0.1\n"
      "  done\n"
      "}\n"
      "BIN=" AG_BIN_DIR "\n" +
      body;
  return RunProgram({"unshare", "-n", "sh", "-c", script});
}

bool CanUnshareNetwork() { return RunProgram({"unshare", "-n", "true"}).exit_code == 0; }

std::vector<std::string> Lines(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

TEST(LiveAcrossProcesses, ServesMapsSkipsGarbageAndCachesRepeats) {
  if (!CanUnshareNetwork()) GTEST_SKIP() << "unshare -n is not permitted here";
  TempDir dir;
  const std::string d = dir.path();
  const std::string two_rooms = SourcePath("examples/two_rooms.png");
  const std::string corridor = SourcePath("examples/corridor_rooms.png");
  const testing::CommandResult result = RunInPrivateNetwork(
      "D=" + d + "\n" +
      "$BIN/ag-live --store $D/live.db --count 3 --timeout 300 >$D/live.out 2>$D/live.err &\n"
      "LIVE=$!; PIDS=\"$PIDS $LIVE\"\n"
      "$BIN/ag-listen --store $D/listen.db --count 3 --timeout 300 >$D/listen.out "
      "2>$D/listen.err &\n"
      "LISTEN=$!; PIDS=\"$PIDS $LISTEN\"\n"
      "$BIN/area_graph_subscriber 'udpm://239.255.76.67:7667?ttl=0' 1 >$D/example.out "
      "2>$D/example.err &\n"
      "EXAMPLE=$!; PIDS=\"$PIDS $EXAMPLE\"\n"
      "wait_for $D/live.err 'ag-live: serving'\n"
      "wait_for $D/listen.err 'ag-listen: listening'\n"
      "wait_for $D/example.err 'listening'\n"
      "$BIN/ag-test-send-map --garbage 200 || exit 92\n"
      "wait_for $D/live.err 'malformed'\n"
      "$BIN/ag-test-send-map " +
      two_rooms +
      " || exit 93\n"
      "wait_for $D/live.out 'two_rooms:'\n"
      "$BIN/ag-test-send-map " +
      two_rooms +
      " || exit 94\n"
      "wait_for $D/live.out 'cached'\n"
      "$BIN/ag-test-send-map " +
      corridor +
      " || exit 95\n"
      "wait $LIVE; echo \"live exit $?\"\n"
      "wait $LISTEN; echo \"listen exit $?\"\n"
      "wait $EXAMPLE; echo \"example exit $?\"\n");
  ASSERT_EQ(result.exit_code, 0) << result.out << result.err;
  EXPECT_NE(result.out.find("live exit 0"), std::string::npos)
      << result.out << ReadFile(d + "/live.err");
  EXPECT_NE(result.out.find("listen exit 0"), std::string::npos)
      << result.out << ReadFile(d + "/listen.err");
  EXPECT_NE(result.out.find("example exit 0"), std::string::npos)
      << result.out << ReadFile(d + "/example.err");

  // ag-live: the garbage was reported and skipped, then three maps served,
  // the repeated one from the cache.
  const std::string live_err = ReadFile(d + "/live.err");
  EXPECT_NE(live_err.find("ag-live: skipped a malformed message on MAP (200 bytes)"),
            std::string::npos)
      << live_err;
  const std::vector<std::string> live = Lines(ReadFile(d + "/live.out"));
  ASSERT_EQ(live.size(), 3u) << ReadFile(d + "/live.out");
  const std::regex line(
      "(\\w+): (\\d+) areas, (\\d+) passages, key ([0-9a-f]{12}), version (\\d+), (.*)");
  std::smatch first, second, third;
  ASSERT_TRUE(std::regex_match(live[0], first, line)) << live[0];
  ASSERT_TRUE(std::regex_match(live[1], second, line)) << live[1];
  ASSERT_TRUE(std::regex_match(live[2], third, line)) << live[2];
  EXPECT_EQ(first[1].str(), "two_rooms");
  EXPECT_EQ(first[5].str(), "1");
  EXPECT_EQ(first[6].str().rfind("computed 7 of 7 stages", 0), 0u) << live[0];
  EXPECT_EQ(second[1].str(), "two_rooms");
  EXPECT_EQ(second[4].str(), first[4].str());
  EXPECT_EQ(second[5].str(), "1");
  EXPECT_EQ(second[6].str().rfind("cached, published ", 0), 0u) << live[1];
  EXPECT_EQ(third[1].str(), "corridor_rooms");
  EXPECT_EQ(third[6].str().rfind("computed 7 of 7 stages", 0), 0u) << live[2];

  // ag-listen heard the same three graphs and stored two distinct ones.
  const std::vector<std::string> heard = Lines(ReadFile(d + "/listen.out"));
  ASSERT_EQ(heard.size(), 3u) << ReadFile(d + "/listen.out") << ReadFile(d + "/listen.err");
  EXPECT_EQ(heard[0], "map two_rooms: " + first[2].str() + " areas, " + first[3].str() +
                          " passages, key " + first[4].str() + ", version 1, stored");
  EXPECT_EQ(heard[1], "map two_rooms: " + first[2].str() + " areas, " + first[3].str() +
                          " passages, key " + first[4].str() + ", version 1, already stored");
  EXPECT_EQ(heard[2], "map corridor_rooms: " + third[2].str() + " areas, " + third[3].str() +
                          " passages, key " + third[4].str() + ", version 1, stored");

  // The listener's store holds the graph ag-live made, linked by its key.
  const auto live_store = OpenArtifactStore(d + "/live.db", StoreMode::kReadOnly);
  const auto listen_store = OpenArtifactStore(d + "/listen.db", StoreMode::kReadOnly);
  for (const std::string map : {"two_rooms", "corridor_rooms"}) {
    std::string live_key;
    const auto made = ReadHeadArtifact<proto::AreaGraph>(*live_store, map, kMatchStage, &live_key);
    const auto received = ReadHeadArtifact<proto::AreaGraph>(*listen_store, map, kMergeStage);
    EXPECT_NE(listen_store->ReadHead(map, "merge")->options_text.find(live_key), std::string::npos);
    EXPECT_EQ(received.areas_size(), made.areas_size());
    EXPECT_EQ(received.passages_size(), made.passages_size());
  }

  // ag-export writes the same GeoJSON from the received copy as from the original.
  const std::string original = d + "/original.geojson", copy = d + "/copy.geojson";
  ASSERT_EQ(testing::RunTool("ag-export", {"--store", d + "/live.db", "--map", "two_rooms",
                                           "--format", "geojson", "--out", original})
                .exit_code,
            0);
  ASSERT_EQ(testing::RunTool("ag-export", {"--store", d + "/listen.db", "--map", "two_rooms",
                                           "--format", "geojson", "--out", copy})
                .exit_code,
            0);
  EXPECT_EQ(ReadFile(copy), ReadFile(original));
  EXPECT_NE(ReadFile(copy).find("Polygon"), std::string::npos);

  // The example subscriber printed the first graph with its areas.
  const std::string example = ReadFile(d + "/example.out");
  EXPECT_EQ(example.find("AREA_GRAPH: map 'two_rooms', " + first[2].str() + " areas"), 0u)
      << example;
  EXPECT_NE(example.find("  area 0: "), std::string::npos) << example;
}

// A map that grows between two grids: ag-live publishes version 1, then
// version 2 with the same ids for what it saw before, and a diff; ag-listen
// and the example subscriber get exactly what ag-live stored.
TEST(LiveAcrossProcesses, IdsAndVersionsArriveAsStored) {
  if (!CanUnshareNetwork()) GTEST_SKIP() << "unshare -n is not permitted here";
  TempDir dir;
  const std::string d = dir.path();
  const cv::Mat whole = cv::imread(SourcePath("examples/corridor_rooms.png"), cv::IMREAD_GRAYSCALE);
  ASSERT_FALSE(whole.empty());
  cv::Mat part = whole.clone();
  part.colRange(whole.cols * 6 / 10, whole.cols).setTo(205);  // unknown
  ASSERT_TRUE(cv::imwrite(d + "/part.png", part));
  ASSERT_TRUE(cv::imwrite(d + "/whole.png", whole));
  const testing::CommandResult result = RunInPrivateNetwork(
      "D=" + d + "\n" +
      "$BIN/ag-live --diffs --store $D/live.db --count 2 --timeout 300 >$D/live.out "
      "2>$D/live.err &\n"
      "LIVE=$!; PIDS=\"$PIDS $LIVE\"\n"
      "$BIN/ag-listen --diffs --store $D/listen.db --count 2 --timeout 300 >$D/listen.out "
      "2>$D/listen.err &\n"
      "LISTEN=$!; PIDS=\"$PIDS $LISTEN\"\n"
      "$BIN/area_graph_subscriber 'udpm://239.255.76.67:7667?ttl=0' 2 >$D/example.out "
      "2>$D/example.err &\n"
      "EXAMPLE=$!; PIDS=\"$PIDS $EXAMPLE\"\n"
      "wait_for $D/live.err 'ag-live: serving'\n"
      "wait_for $D/listen.err 'ag-listen: listening'\n"
      "wait_for $D/example.err 'listening'\n"
      "$BIN/ag-test-send-map --name robot $D/part.png || exit 93\n"
      "wait_for $D/live.out 'version 1'\n"
      "$BIN/ag-test-send-map --name robot $D/whole.png || exit 94\n"
      "wait $LIVE; echo \"live exit $?\"\n"
      "wait $LISTEN; echo \"listen exit $?\"\n"
      "wait $EXAMPLE; echo \"example exit $?\"\n");
  ASSERT_EQ(result.exit_code, 0) << result.out << result.err << ReadFile(d + "/live.err")
                                 << ReadFile(d + "/listen.err");
  EXPECT_NE(result.out.find("live exit 0"), std::string::npos) << ReadFile(d + "/live.err");
  EXPECT_NE(result.out.find("listen exit 0"), std::string::npos) << ReadFile(d + "/listen.err");
  EXPECT_NE(result.out.find("example exit 0"), std::string::npos) << ReadFile(d + "/example.err");

  const auto live_store = OpenArtifactStore(d + "/live.db", StoreMode::kReadOnly);
  const std::vector<VersionRecord> history = live_store->ReadVersions("robot");
  ASSERT_EQ(history.size(), 2u);
  EXPECT_EQ(history[1].predecessor_key, history[0].cache_key);
  std::string live_key;
  const auto made =
      ReadHeadArtifact<proto::AreaGraph>(*live_store, "robot", kMatchStage, &live_key);
  EXPECT_EQ(live_key, history[1].cache_key);
  const auto first = ReadArtifactAs<proto::AreaGraph>(*live_store, "robot", history[0].cache_key);
  int kept = 0;
  for (const proto::Area& area : first.areas()) {
    for (const proto::Area& now : made.areas()) kept += now.stable_id() == area.stable_id();
  }
  EXPECT_GE(kept, 1);

  // ag-listen stored version 2 with ag-live's ids, in ag-live's order.
  const auto listen_store = OpenArtifactStore(d + "/listen.db", StoreMode::kReadOnly);
  const auto received = ReadHeadArtifact<proto::AreaGraph>(*listen_store, "robot", kMergeStage);
  EXPECT_EQ(received.version().number(), 2);
  EXPECT_EQ(received.version().predecessor_key(), history[0].cache_key);
  ASSERT_EQ(received.areas_size(), made.areas_size());
  for (int i = 0; i < made.areas_size(); ++i) {
    EXPECT_EQ(received.areas(i).stable_id(), made.areas(i).stable_id()) << i;
  }
  ASSERT_EQ(received.passages_size(), made.passages_size());
  for (int i = 0; i < made.passages_size(); ++i) {
    EXPECT_EQ(received.passages(i).stable_id(), made.passages(i).stable_id()) << i;
    EXPECT_EQ(received.areas(received.passages(i).area_a()).stable_id(),
              made.areas(made.passages(i).area_a()).stable_id());
  }
  const std::vector<std::string> heard = Lines(ReadFile(d + "/listen.out"));
  ASSERT_EQ(heard.size(), 3u) << ReadFile(d + "/listen.out");
  EXPECT_EQ(heard[0].rfind("map robot: ", 0), 0u);
  EXPECT_NE(heard[0].find(", key " + history[0].cache_key.substr(0, 12) + ", version 1, stored"),
            std::string::npos)
      << heard[0];
  // The diff comes just before the graph it leads to.
  EXPECT_EQ(heard[1].rfind("diff robot: version 1 -> 2, areas +", 0), 0u) << heard[1];
  EXPECT_NE(heard[2].find(", key " + live_key.substr(0, 12) + ", version 2, stored"),
            std::string::npos)
      << heard[2];

  const std::string example = ReadFile(d + "/example.out");
  EXPECT_NE(example.find("(key " + live_key.substr(0, 12) + ", version 2, message 1, sent at "),
            std::string::npos)
      << example;
  for (const proto::Area& area : made.areas()) {
    EXPECT_NE(example.find("  area " + std::to_string(area.stable_id()) + ": "), std::string::npos)
        << area.stable_id() << "\n"
        << example;
  }
}

TEST(LiveAcrossProcesses, SaysHowToFixAMissingMulticastRoute) {
  if (!CanUnshareNetwork()) GTEST_SKIP() << "unshare -n is not permitted here";
  TempDir dir;
  // A fresh namespace has its loopback down and no routes at all.
  for (const std::string tool : {"ag-live", "ag-listen"}) {
    const testing::CommandResult result =
        RunProgram({"unshare", "-n", std::string(AG_BIN_DIR) + "/" + tool, "--store",
                    dir.File("x.db"), "--timeout", "1"});
    EXPECT_EQ(result.exit_code, 1) << result.err;
    EXPECT_NE(result.err.find(tool + ": cannot open LCM at 'udpm://239.255.76.67:7667?ttl=0"),
              std::string::npos)
        << result.err;
    EXPECT_NE(result.err.find("ip route add 224.0.0.0/4 dev lo"), std::string::npos);
  }
}

TEST(LiveAcrossProcesses, StopsCleanlyOnSigterm) {
  if (!CanUnshareNetwork()) GTEST_SKIP() << "unshare -n is not permitted here";
  TempDir dir;
  const testing::CommandResult result =
      RunInPrivateNetwork("D=" + dir.path() + "\n" +
                          "$BIN/ag-live --store $D/live.db >$D/live.out 2>$D/live.err &\n"
                          "LIVE=$!; PIDS=\"$PIDS $LIVE\"\n"
                          "wait_for $D/live.err 'ag-live: serving'\n"
                          "kill -TERM $LIVE\n"
                          "wait $LIVE; echo \"live exit $?\"\n");
  ASSERT_EQ(result.exit_code, 0) << result.out << result.err;
  EXPECT_NE(result.out.find("live exit 0"), std::string::npos) << result.out;
  const std::string live_err = ReadFile(dir.path() + "/live.err");
  EXPECT_NE(live_err.find("stopped by signal"), std::string::npos) << live_err;
  // It restarted once at start-up for huge pages (a grid's size is not known
  // before it arrives); the signal found the restarted process.
  EXPECT_EQ(testing::CountOccurrences(live_err, "ag-live: restarted with glibc.malloc.hugetlb=1\n"),
            1)
      << live_err;
}

}  // namespace
}  // namespace areagraph

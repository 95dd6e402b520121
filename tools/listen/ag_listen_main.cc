// ag-listen: prints the Area Graphs published on LCM channel AREA_GRAPH (by
// ag-run --publish or ag-live), one line each, and can save them in a store.
#include <CLI/CLI.hpp>
#include <algorithm>
#include <chrono>
#include <csignal>
#include <iostream>
#include <memory>

#include "runner/live/area_graph_publisher.h"
#include "runner/live/lcm_connection.h"
#include "stages/common/command_line.h"
#include "store/artifact_store.h"
#include "store/error.h"
#include "tools/listen/area_graph_listener.h"

namespace areagraph {
namespace {

volatile std::sig_atomic_t stop_requested = 0;

void RequestStop(int) { stop_requested = 1; }

struct ListenFlags {
  std::string url = kDefaultLcmUrl;
  std::string store_path;
  int count = 0;
  double timeout_s = 0;
};

int Listen(const ListenFlags& flags) {
  if (flags.count < 0) throw OptionsError("--count must be 0 (no limit) or positive");
  if (!(flags.timeout_s >= 0)) throw OptionsError("--timeout must be 0 (none) or positive");
  const std::string url = ReceivingLcmUrl(flags.url);
  std::unique_ptr<ArtifactStore> store;
  if (!flags.store_path.empty()) store = OpenArtifactStore(flags.store_path);
  const std::unique_ptr<lcm::LCM> lcm = OpenLcm(url);
  AreaGraphListener listener(*lcm, url, store.get(), std::cout, std::cerr);

  struct sigaction action = {};
  action.sa_handler = RequestStop;
  sigemptyset(&action.sa_mask);
  sigaction(SIGINT, &action, nullptr);
  sigaction(SIGTERM, &action, nullptr);
  std::cerr << "ag-listen: listening on " << url << ", channel " << kAreaGraphChannel << std::endl;

  using Clock = std::chrono::steady_clock;
  const Clock::time_point deadline =
      Clock::now() +
      std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(flags.timeout_s));
  while (!stop_requested && (flags.count == 0 || listener.graphs_received() < flags.count)) {
    int wait_ms = 200;
    if (flags.timeout_s > 0) {
      const auto left =
          std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now());
      if (left.count() <= 0) break;
      wait_ms = static_cast<int>(std::min<int64_t>(wait_ms, left.count()));
    }
    listener.Listen(wait_ms);
  }
  if (flags.count > 0 && listener.graphs_received() < flags.count && !stop_requested) {
    throw Error("--timeout reached after " + std::to_string(listener.graphs_received()) + " of " +
                std::to_string(flags.count) + " graphs");
  }
  return 0;
}

}  // namespace
}  // namespace areagraph

int main(int argc, char** argv) {
  using namespace areagraph;
  CLI::App app{
      "Prints one line per Area Graph (areagraph_lcm.area_graph_t, see proto/area_graph_t.lcm) "
      "received on LCM channel AREA_GRAPH: map, areas, passages and key. With --store, each "
      "graph also becomes its map's merge artifact and head in that store, under a key derived "
      "from the publisher's (so the same graph is stored once). Malformed messages are reported "
      "on stderr and skipped."};
  ListenFlags flags;
  app.add_option("--url", flags.url, "LCM URL; udpm must keep ttl=0 (traffic stays on the host)")
      ->capture_default_str();
  app.add_option("--store", flags.store_path, "save received graphs in this SQLite store");
  app.add_option("--count", flags.count, "exit after this many graphs (0: no limit)")
      ->capture_default_str();
  app.add_option("--timeout", flags.timeout_s,
                 "exit after this many seconds (0: never); an error if --count was not reached")
      ->capture_default_str();
  return RunCommand("ag-listen", app, argc, argv, [&] { return Listen(flags); });
}

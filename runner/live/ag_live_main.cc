// ag-live: turns occupancy grids arriving over LCM (channel MAP, for example
// from a robot's SLAM) into Area Graphs published on AREA_GRAPH, with the
// store's cache so that a grid sent again costs nothing.
#include <CLI/CLI.hpp>
#include <algorithm>
#include <chrono>
#include <csignal>
#include <iostream>

#include "runner/live/area_graph_publisher.h"
#include "runner/live/lcm_connection.h"
#include "runner/live/live_map_server.h"
#include "stages/common/command_line.h"
#include "store/artifact_store.h"
#include "store/error.h"

namespace areagraph {
namespace {

volatile std::sig_atomic_t stop_requested = 0;

void RequestStop(int) { stop_requested = 1; }

// SIGINT and SIGTERM end the loop after the map in hand.
void InstallStopHandlers() {
  struct sigaction action = {};
  action.sa_handler = RequestStop;
  sigemptyset(&action.sa_mask);
  sigaction(SIGINT, &action, nullptr);
  sigaction(SIGTERM, &action, nullptr);
}

struct LiveFlags {
  std::string url = kDefaultLcmUrl;
  StageCommandLine stage;
  int count = 0;
  double timeout_s = 0;
};

int Live(const LiveFlags& flags) {
  if (flags.count < 0) throw OptionsError("--count must be 0 (no limit) or positive");
  if (!(flags.timeout_s >= 0)) throw OptionsError("--timeout must be 0 (none) or positive");
  const proto::PipelineOptions options = LoadPipelineOptions(flags.stage);
  if (options.import().max_pixels() <= 0) {
    throw OptionsError("import.max_pixels must be positive");
  }
  // Everything that can fail without the network fails before LCM starts.
  const std::string url = ReceivingLcmUrl(flags.url);
  const std::unique_ptr<ArtifactStore> store = OpenArtifactStore(flags.stage.store_path);
  AreaGraphPublisher publisher(url);
  LiveMapServer server(*store, publisher, options, std::cout, std::cerr);
  InstallStopHandlers();
  std::cerr << "ag-live: serving on " << publisher.url() << ": grids on " << kGridMapChannel
            << ", Area Graphs on " << kAreaGraphChannel << ", store '" << flags.stage.store_path
            << "'" << std::endl;

  using Clock = std::chrono::steady_clock;
  const Clock::time_point deadline =
      Clock::now() +
      std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(flags.timeout_s));
  while (!stop_requested && (flags.count == 0 || server.maps_handled() < flags.count)) {
    int wait_ms = 200;
    if (flags.timeout_s > 0) {
      const auto left =
          std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now());
      if (left.count() <= 0) break;
      wait_ms = static_cast<int>(std::min<int64_t>(wait_ms, left.count()));
    }
    server.Serve(wait_ms);
  }
  std::cerr << "ag-live: handled " << server.maps_handled() << " maps (" << server.maps_failed()
            << " failed), skipped " << server.messages_rejected() << " malformed messages"
            << (stop_requested ? "; stopped by signal" : "") << std::endl;
  if (flags.count > 0 && server.maps_handled() < flags.count && !stop_requested) {
    throw Error("--timeout reached after " + std::to_string(server.maps_handled()) + " of " +
                std::to_string(flags.count) + " maps");
  }
  return 0;
}

}  // namespace
}  // namespace areagraph

int main(int argc, char** argv) {
  using namespace areagraph;
  CLI::App app{
      "Serves Area Graphs live: subscribes to occupancy grids (areagraph_lcm.grid_map_t, see "
      "proto/grid_map_t.lcm) on LCM channel MAP, runs import..merge on each with the store's "
      "cache (a grid sent again is a cache hit and costs nothing), and publishes the Area Graph "
      "(area_graph_t) on AREA_GRAPH. Malformed messages and failing maps are reported on stderr "
      "and skipped. Stops on SIGINT or SIGTERM after the map in hand."};
  LiveFlags flags;
  app.add_option("--url", flags.url, "LCM URL; udpm must keep ttl=0 (traffic stays on the host)")
      ->capture_default_str();
  app.add_option("--store", flags.stage.store_path, "SQLite artifact store")->capture_default_str();
  app.add_option("--options", flags.stage.options_file,
                 "PipelineOptions in protobuf text format (see examples/options/)");
  app.add_option("--set", flags.stage.overrides,
                 "override one option, e.g. --set cut.room_width_m=1.1 (repeatable)")
      ->take_last()
      ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
  app.add_option("--count", flags.count, "exit after handling this many maps (0: no limit)")
      ->capture_default_str();
  app.add_option("--timeout", flags.timeout_s,
                 "exit after this many seconds (0: never); an error if --count was not reached")
      ->capture_default_str();
  return RunCommand("ag-live", app, argc, argv, [&] { return Live(flags); });
}

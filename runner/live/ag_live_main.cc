// ag-live: turns occupancy grids arriving over LCM (channel MAP, for example
// from a robot's SLAM) into Area Graphs published on AREA_GRAPH, with the
// store's cache so that a grid sent again costs nothing.
#include <CLI/CLI.hpp>
#include <iostream>

#include "common/error.h"
#include "common/process_setup/huge_page_restart.h"
#include "runner/live/area_graph_publisher.h"
#include "runner/live/lcm_connection.h"
#include "runner/live/live_map_server.h"
#include "runner/live/serve_loop.h"
#include "stages/common/command_line.h"
#include "store/write_behind_store.h"

namespace areagraph {
namespace {

struct LiveFlags {
  std::string url;
  StageCommandLine stage;
  ServeLimits limits;
  bool diffs = false;
};

int Live(const LiveFlags& flags) {
  flags.limits.Check();
  const proto::PipelineOptions options = LoadPipelineOptions(flags.stage);
  if (options.import().max_pixels() <= 0) {
    throw OptionsError("import.max_pixels must be positive");
  }
  // Everything that can fail without the network fails before LCM starts.
  const std::string url = ReceivingLcmUrl(flags.url);
  // A grid's size is known only once it arrives, so the server restarts at
  // start-up, while it holds nothing open yet (no store, no LCM, no thread):
  // one 9-ms restart, then any grid's heap grows in huge pages (half the page
  // faults even on a small map; docs/performance.md, "Memory between stages").
  if (MayRestartWithHugePageTunable()) RestartWithHugePageTunable();
  const std::unique_ptr<ArtifactStore> store = OpenWriteBehindStore(flags.stage.store_path);
  AreaGraphPublisher publisher(url);
  LiveMapServer server(*store, publisher, options, std::cout, std::cerr);
  server.set_publish_diffs(flags.diffs);
  std::cerr << "ag-live: serving on " << publisher.url() << ": grids on " << kGridMapChannel
            << ", Area Graphs on " << kAreaGraphChannel
            << (flags.diffs ? std::string(", diffs on ") + kAreaGraphDiffChannel : "")
            << ", store '" << flags.stage.store_path << "'" << std::endl
            << HugePageRestartLine("ag-live") << std::flush;

  const bool stopped = ServeUntilDone(
      flags.limits, "maps", [&] { return server.maps_handled(); },
      [&](int wait_ms) { server.Serve(wait_ms); });
  std::cerr << "ag-live: handled " << server.maps_handled() << " maps (" << server.maps_failed()
            << " failed), skipped " << server.messages_rejected() << " malformed messages"
            << (stopped ? "; stopped by signal" : "") << std::endl;
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
      "(area_graph_t) on AREA_GRAPH, with ids that stay stable from one grid of a map to the "
      "next (ag-match) and its version in the map's history. Prints one line per map: areas, "
      "passages, key, version, work done and the time from receipt to publication. Malformed "
      "messages and failing maps are reported on stderr and skipped. Stops on SIGINT or SIGTERM "
      "after the map in hand. Starts itself again once, at start-up, with glibc's "
      "glibc.malloc.hugetlb=1 in GLIBC_TUNABLES (transparent huge pages for big grids) unless "
      "GLIBC_TUNABLES already sets it (a line on stderr says so)."};
  LiveFlags flags;
  AddLcmUrlFlag(app, flags.url);
  app.add_option("--store", flags.stage.store_path, "SQLite artifact store")->capture_default_str();
  app.add_option("--options", flags.stage.options_file,
                 "PipelineOptions in protobuf text format (see examples/options/)");
  app.add_option("--set", flags.stage.overrides,
                 "override one option, e.g. --set cut.room_width_m=1.1 (repeatable)")
      ->take_last()
      ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
  app.add_flag("--diffs", flags.diffs,
               "also publish what changed since each map's previous version (area_graph_diff_t) "
               "on AREA_GRAPH_DIFF");
  app.add_option("--count", flags.limits.count, "exit after handling this many maps (0: no limit)")
      ->capture_default_str();
  app.add_option("--timeout", flags.limits.timeout_s,
                 "exit after this many seconds (0: never); an error if --count was not reached")
      ->capture_default_str();
  return RunCommand("ag-live", app, argc, argv, [&] { return Live(flags); });
}

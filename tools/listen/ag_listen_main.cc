// ag-listen: prints the Area Graphs published on LCM channel AREA_GRAPH (by
// ag-run --publish or ag-live), one line each, and can save them in a store.
#include <CLI/CLI.hpp>
#include <iostream>
#include <memory>

#include "common/error.h"
#include "runner/live/area_graph_publisher.h"
#include "runner/live/lcm_connection.h"
#include "runner/live/serve_loop.h"
#include "stages/common/command_line.h"
#include "store/artifact_store.h"
#include "tools/listen/area_graph_listener.h"

namespace areagraph {
namespace {

struct ListenFlags {
  std::string url;
  std::string store_path;
  ServeLimits limits;
  bool diffs = false;
};

int Listen(const ListenFlags& flags) {
  flags.limits.Check();
  const std::string url = ReceivingLcmUrl(flags.url);
  std::unique_ptr<ArtifactStore> store;
  if (!flags.store_path.empty()) store = OpenArtifactStore(flags.store_path);
  const std::unique_ptr<lcm::LCM> lcm = OpenLcm(url);
  AreaGraphListener listener(*lcm, url, store.get(), std::cout, std::cerr, flags.diffs);

  std::cerr << "ag-listen: listening on " << url << ", channel " << kAreaGraphChannel
            << (flags.diffs ? std::string(" and ") + kAreaGraphDiffChannel : "") << std::endl;

  ServeUntilDone(
      flags.limits, "graphs", [&] { return listener.graphs_received(); },
      [&](int wait_ms) { listener.Listen(wait_ms); });
  return 0;
}

}  // namespace
}  // namespace areagraph

int main(int argc, char** argv) {
  using namespace areagraph;
  CLI::App app{
      "Prints one line per Area Graph (areagraph_lcm.area_graph_t, see proto/area_graph_t.lcm) "
      "received on LCM channel AREA_GRAPH: map, areas, passages, key and version. With --diffs, "
      "also one line per diff on AREA_GRAPH_DIFF (ag-live --diffs). With --store, each "
      "graph also becomes its map's merge artifact and head in that store, under a key derived "
      "from the publisher's (so the same graph is stored once). Malformed messages are reported "
      "on stderr and skipped."};
  ListenFlags flags;
  AddLcmUrlFlag(app, flags.url);
  app.add_option("--store", flags.store_path, "save received graphs in this SQLite store");
  app.add_flag("--diffs", flags.diffs,
               "also print the diffs (area_graph_diff_t) received on AREA_GRAPH_DIFF");
  app.add_option("--count", flags.limits.count, "exit after this many graphs (0: no limit)")
      ->capture_default_str();
  app.add_option("--timeout", flags.limits.timeout_s,
                 "exit after this many seconds (0: never); an error if --count was not reached")
      ->capture_default_str();
  return RunCommand("ag-listen", app, argc, argv, [&] { return Listen(flags); });
}

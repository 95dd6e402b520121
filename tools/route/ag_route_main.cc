// ag-route: the shortest route between two points of a stored map, through
// its Area Graph.
#include <CLI/CLI.hpp>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <memory>
#include <string>

#include "common/error.h"
#include "common/json.h"
#include "stages/common/command_line.h"
#include "store/artifact_store.h"
#include "tools/route/area_router.h"
#include "tools/route/route_report.h"
#include "tools/route/stored_graph.h"

namespace {

// "X,Y" in metres; throws OptionsError naming `flag` otherwise.
areagraph::Vec2 ParsePoint(const std::string& text, const std::string& flag) {
  const size_t comma = text.find(',');
  if (comma != std::string::npos) {
    const std::string x_text = text.substr(0, comma), y_text = text.substr(comma + 1);
    char* x_end = nullptr;
    char* y_end = nullptr;
    const double x = std::strtod(x_text.c_str(), &x_end);
    const double y = std::strtod(y_text.c_str(), &y_end);
    if (!x_text.empty() && !y_text.empty() && *x_end == '\0' && *y_end == '\0' &&
        std::isfinite(x) && std::isfinite(y)) {
      return {x, y};
    }
  }
  throw areagraph::OptionsError(flag + " must be X,Y in metres (map frame), e.g. " + flag +
                                " 1.5,-2; got '" + text + "'");
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{
      "Finds the shortest route between two points of a stored map through its Area Graph "
      "(the newest, as ag-export picks it): straight lines through the areas that bend only at "
      "corners, crossing passages anywhere along their border. A point outside every area "
      "starts from the nearest area within 1 m. Prints the length, the areas and passages on "
      "the way (stable ids) and the polyline, in metres in the map frame; no route is an "
      "error (exit 1)."};
  std::string store_path = "areagraph.db", map_name, from_text, to_text, version;
  bool json = false;
  app.add_option("--store", store_path, "SQLite artifact store")->capture_default_str();
  app.add_option("--map", map_name, "name of the map in the store")->required();
  app.add_option("--from", from_text, "start X,Y in metres")->required();
  app.add_option("--to", to_text, "goal X,Y in metres")->required();
  app.add_option("--graph-version", version,
                 "the Area Graph version to use: a number, a key prefix or head (default: the "
                 "newest graph)");
  app.add_flag("--json", json, "print the route as JSON (RouteReport, tools/route)");
  return areagraph::RunCommand("ag-route", app, argc, argv, [&] {
    const areagraph::Vec2 start = ParsePoint(from_text, "--from");
    const areagraph::Vec2 goal = ParsePoint(to_text, "--to");
    const std::unique_ptr<areagraph::ArtifactStore> store =
        areagraph::OpenArtifactStore(store_path, areagraph::StoreMode::kReadOnly);
    const areagraph::proto::AreaGraph graph =
        areagraph::ReadStoredAreaGraph(*store, map_name, version);
    const areagraph::AreaRouter router(graph);
    const areagraph::RouteAnswer answer = router.FindRoute(start, goal);
    if (!answer.route) throw areagraph::Error("no route: " + answer.no_route_reason);
    const areagraph::route::RouteReport report =
        areagraph::ReportRoute(graph, map_name, start, goal, *answer.route);
    std::cout << (json ? areagraph::MessageToJson(report) + "\n" : areagraph::RouteText(report));
    return 0;
  });
}

// ag-bench-route: routes through a stored map's Area Graph (ag-route's
// router) against the shortest 8-connected path through the map's free
// cells, over random pairs of free cells: how much longer the routes are,
// and how long a query takes after the router's set-up, beside a grid A* and
// Dijkstra on the same map. Prints one row of tools/bench-route.sh's table.
#include <CLI/CLI.hpp>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "common/error.h"
#include "common/text.h"
#include "stages/common/command_line.h"
#include "stages/common/map_frame.h"
#include "stages/pipeline/stage.h"
#include "store/artifact_store.h"
#include "tools/bench/grid_geodesic.h"
#include "tools/bench/median_timer.h"
#include "tools/route/area_router.h"
#include "tools/route/stored_graph.h"

namespace areagraph {
namespace {

struct Settings {
  std::string store_path = "areagraph.db";
  std::string map_name;
  int pairs = 200;
  int dijkstra_pairs = 30;
  unsigned seed = 1;
  double min_distance_m = 3;
  bool list_outliers = false;
  RouteSettings route;
  GridPathRules grid;
};

double Percentile(std::vector<double> values, double share) {
  if (values.empty()) return 0;
  std::sort(values.begin(), values.end());
  return values[std::min(values.size() - 1, static_cast<size_t>(share * values.size()))];
}

int Run(const Settings& settings) {
  const std::unique_ptr<ArtifactStore> store =
      OpenArtifactStore(settings.store_path, StoreMode::kReadOnly);
  const auto grid = ReadHeadArtifact<proto::GridMap>(*store, settings.map_name, kImportStage);
  const proto::AreaGraph graph = ReadStoredAreaGraph(*store, settings.map_name);
  GridGeodesic geodesic(grid, settings.grid);
  const MapTransform transform(grid.frame());
  std::unique_ptr<AreaRouter> router;
  const double setup_ms =
      ElapsedMs([&] { router = std::make_unique<AreaRouter>(graph, settings.route); });

  std::vector<int> free_cells;
  for (int cell = 0; cell < geodesic.width() * geodesic.height(); ++cell) {
    if (geodesic.Free(cell)) free_cells.push_back(cell);
  }
  if (free_cells.empty()) throw InputError("map '" + settings.map_name + "' has no free cells");
  auto centre = [&](int cell) {
    return transform.PixelToWorld(
        Eigen::Vector2d(cell % geodesic.width() + 0.5, cell / geodesic.width() + 0.5));
  };
  std::mt19937 random(settings.seed);
  std::uniform_int_distribution<size_t> pick(0, free_cells.size() - 1);
  std::vector<double> excess, query_ms, astar_ms, dijkstra_ms;
  int pairs = 0, no_route = 0, over_limit = 0;
  for (int attempt = 0; pairs < settings.pairs && attempt < 1000 * settings.pairs; ++attempt) {
    const int from = free_cells[pick(random)], to = free_cells[pick(random)];
    const Vec2 start = centre(from), goal = centre(to);
    if ((goal - start).norm() < settings.min_distance_m) continue;
    if (geodesic.Component(from) != geodesic.Component(to)) continue;
    ++pairs;
    double grid_length = 0;
    astar_ms.push_back(ElapsedMs([&] { grid_length = geodesic.Length(from, to, true); }));
    if (static_cast<int>(dijkstra_ms.size()) < settings.dijkstra_pairs) {
      dijkstra_ms.push_back(ElapsedMs([&] { geodesic.Length(from, to, false); }));
    }
    RouteAnswer answer;
    query_ms.push_back(ElapsedMs([&] { answer = router->FindRoute(start, goal); }));
    if (!answer.route) {
      ++no_route;
      if (settings.list_outliers) {
        std::fprintf(stderr, "no route (%.3f, %.3f) -> (%.3f, %.3f): %s\n", start.x(), start.y(),
                     goal.x(), goal.y(), answer.no_route_reason.c_str());
      }
      continue;
    }
    excess.push_back(100 * (answer.route->length_m / grid_length - 1));
    if (excess.back() > 15) {
      ++over_limit;
      if (settings.list_outliers) {
        std::fprintf(stderr, "%+.1f %% (%.3f, %.3f) -> (%.3f, %.3f): route %.3f m, grid %.3f m\n",
                     excess.back(), start.x(), start.y(), goal.x(), goal.y(),
                     answer.route->length_m, grid_length);
      }
    }
  }
  std::string rules = settings.grid.clearance_m > 0
                          ? "free, >= " + FormatNumber(settings.grid.clearance_m) + " m clear"
                          : "free";
  if (settings.grid.no_corner_cutting) rules += ", no corner cutting";
  std::printf(
      "| %s | %s | %dx%d | %d | %d / %lld | %.0f | %d | %d | %d | %+.1f | %+.1f | %d | %.3f | "
      "%.3f | %.2f | %.1f |\n",
      settings.map_name.c_str(), rules.c_str(), geodesic.width(), geodesic.height(),
      graph.areas_size(), router->corner_count(), static_cast<long long>(router->link_count()),
      setup_ms, pairs, pairs - no_route, no_route, Median(excess),
      excess.empty() ? 0 : *std::max_element(excess.begin(), excess.end()), over_limit,
      Median(query_ms), Percentile(query_ms, 0.9), Median(astar_ms), Median(dijkstra_ms));
  return 0;
}

}  // namespace
}  // namespace areagraph

int main(int argc, char** argv) {
  areagraph::Settings settings;
  CLI::App app{
      "Routes through a stored map's Area Graph against the shortest 8-connected path through "
      "its free cells (the import's grid; diagonal steps cost sqrt 2), over random pairs of free "
      "cells in one part of the map, at least --min-distance-m apart. Prints one Markdown "
      "row: map, which cells the grid paths use, cells, areas, corners / links, router set-up ms, "
      "pairs, routed, without route, "
      "median and max excess of the route over the grid path (%), routes over 15 %, route "
      "query median and 90th percentile ms, grid A* and grid Dijkstra median ms."};
  app.add_option("--store", settings.store_path, "SQLite artifact store")->capture_default_str();
  app.add_option("--map", settings.map_name, "name of the map in the store")->required();
  app.add_option("--pairs", settings.pairs, "pairs of points")->capture_default_str();
  app.add_option("--dijkstra-pairs", settings.dijkstra_pairs,
                 "pairs also timed with Dijkstra's algorithm")
      ->capture_default_str();
  app.add_option("--seed", settings.seed, "random seed")->capture_default_str();
  app.add_option("--link-hops", settings.route.link_hops, "RouteSettings.link_hops")
      ->capture_default_str();
  app.add_option("--end-hops", settings.route.end_hops, "RouteSettings.end_hops")
      ->capture_default_str();
  app.add_option("--clearance-m", settings.grid.clearance_m,
                 "grid paths keep at least this far from occupied and unknown cells (cell "
                 "centre to cell edge)")
      ->capture_default_str();
  app.add_flag("--no-corner-cutting", settings.grid.no_corner_cutting,
               "a diagonal grid step needs both cells beside it free");
  app.add_flag("--list-outliers", settings.list_outliers,
               "list on stderr the pairs without a route or more than 15 % longer");
  app.add_option("--min-distance-m", settings.min_distance_m,
                 "least straight distance between the two points")
      ->capture_default_str();
  return areagraph::RunCommand("ag-bench-route", app, argc, argv,
                               [&] { return areagraph::Run(settings); });
}

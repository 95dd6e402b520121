// ag-export: writes a map's Area Graph (the newest: the ag-match head, with
// stable ids, unless ag-merge ran after it) as a label image, GeoJSON, osmAG
// XML or JSON, or the whole run as an HTML viewer.
#include <CLI/CLI.hpp>
#include <iostream>
#include <string>

#include "common/error.h"
#include "proto/artifacts.pb.h"
#include "stages/common/command_line.h"
#include "stages/common/stage.h"
#include "stages/common/stage_versions.h"
#include "store/artifact_store.h"
#include "tools/export/area_graph_export.h"
#include "tools/export/html_viewer.h"

int main(int argc, char** argv) {
  CLI::App app{
      "Writes the Area Graph of one map in another format.\n"
      "  labels   16-bit PNG the size of the map: 0 = no area, area id + 1 inside each area\n"
      "  geojson  FeatureCollection in map metres: areas as Polygons, passages as LineStrings\n"
      "  osmag    osmAG XML for JOSM: areas as closed ways, passages as two-node ways\n"
      "  json     the AreaGraph message as JSON\n"
      "  html     one self-contained page to inspect every stage in a browser (layers, hover,\n"
      "           zoom, options, times); --compare KEY shows a second run beside it"};
  std::string store_path = "areagraph.db", map_name, format_name, out_path, key, compare_key;
  areagraph::GeoAnchor anchor;
  app.add_option("--store", store_path, "SQLite artifact store")->capture_default_str();
  app.add_option("--map", map_name, "name of the map in the store")->required();
  app.add_option("--format", format_name, "labels, geojson, osmag, json or html")->required();
  app.add_option("--out", out_path, "file to write")->required();
  app.add_option("--anchor-lat", anchor.lat_deg,
                 "osmag: latitude of the map's world origin in degrees (default 31.17947)");
  app.add_option("--anchor-lon", anchor.lon_deg,
                 "osmag: longitude of the map's world origin in degrees (default 121.59042)");
  app.add_option("--key", key,
                 "html: show the run behind this artifact key (prefix; default: heads)");
  app.add_option("--compare", compare_key, "html: a second key of the map to compare with");
  return areagraph::RunCommand("ag-export", app, argc, argv, [&] {
    if (format_name == "html")
      return areagraph::ExportViewerPage(store_path, map_name, key, compare_key, out_path);
    if (!key.empty() || !compare_key.empty()) {
      throw areagraph::OptionsError("--key and --compare go with --format html");
    }
    areagraph::ExportSettings settings;
    settings.format = areagraph::ParseExportFormat(format_name);
    settings.map_name = map_name;
    settings.anchor = anchor;
    if (anchor.lat_deg < -89 || anchor.lat_deg > 89 || anchor.lon_deg < -180 ||
        anchor.lon_deg > 180) {
      throw areagraph::OptionsError(
          "--anchor-lat must be in [-89, 89] and --anchor-lon in "
          "[-180, 180]");
    }
    auto store = areagraph::OpenArtifactStore(store_path, areagraph::StoreMode::kReadOnly);
    const std::optional<std::string> graph_key = areagraph::NewestGraphKey(*store, map_name);
    if (!graph_key) {
      throw areagraph::InputError(
          store->ReadMap(map_name) ? "map '" + map_name + "' has no Area Graph; run ag-merge first"
                                   : "map '" + map_name + "' is not in the store");
    }
    const auto graph =
        areagraph::ReadArtifactAs<areagraph::proto::AreaGraph>(*store, map_name, *graph_key);
    areagraph::WriteExportFile(out_path, areagraph::ExportAreaGraph(graph, settings));
    return 0;
  });
}

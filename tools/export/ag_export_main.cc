// ag-export: writes a map's Area Graph (the newest: the ag-match head, with
// stable ids, unless ag-merge ran after it) as a label image, a colour
// preview, GeoJSON, osmAG XML or JSON, or the whole run as an HTML viewer.
#include <CLI/CLI.hpp>
#include <algorithm>
#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

#include "common/error.h"
#include "common/text.h"
#include "proto/artifacts.pb.h"
#include "stages/common/command_line.h"
#include "stages/common/output_file.h"
#include "stages/common/pipeline_options.h"
#include "stages/pipeline/stage.h"
#include "stages/pipeline/stage_versions.h"
#include "store/artifact_store.h"
#include "tools/export/area_graph_export.h"
#include "tools/export/geo_anchor.h"
#include "tools/export/html_viewer.h"

namespace {

// "a, b, c" for `separator` ", ".
std::string Join(const std::vector<std::string>& items, const std::string& separator) {
  std::string joined;
  for (const std::string& item : items) joined += (joined.empty() ? "" : separator) + item;
  return joined;
}

// Throws OptionsError when one of `options` was given but the format is none of `formats`.
void RequireFormatFor(const CLI::App& app, const std::string& format_name,
                      const std::vector<std::string>& formats,
                      std::initializer_list<const char*> options) {
  if (std::find(formats.begin(), formats.end(), format_name) != formats.end()) return;
  for (const char* option : options) {
    if (app.count(option) > 0) {
      throw areagraph::OptionsError(std::string(option) + " goes with --format " +
                                    Join(formats, " or "));
    }
  }
}

// Writes the newest Area Graph of every map of `store` into `folder` as
// <map><suffix> (a map named with folders gets them). The maps without an
// Area Graph are named on one line of stderr and make the status 1, as a
// failed map does in ag-run.
int ExportEveryMap(areagraph::ArtifactStore& store, areagraph::ExportSettings settings,
                   const std::string& store_path, const std::string& folder) {
  if (areagraph::IsStandardOutput(folder)) {
    throw areagraph::OptionsError("--all writes a file per map: give --out a folder");
  }
  const std::vector<areagraph::MapRecord> maps = store.ReadAllMaps();
  if (maps.empty()) throw areagraph::InputError("the store '" + store_path + "' holds no maps");
  std::vector<std::string> missing;
  for (const areagraph::MapRecord& map : maps) {
    const std::optional<std::string> graph_key = areagraph::NewestGraphKey(store, map.name);
    if (!graph_key) {
      missing.push_back(map.name);
      continue;
    }
    const auto graph =
        areagraph::ReadArtifactAs<areagraph::proto::AreaGraph>(store, map.name, *graph_key);
    settings.map_name = map.name;
    const std::filesystem::path target =
        std::filesystem::path(folder) / (map.name + areagraph::ExportFileSuffix(settings.format));
    std::error_code error;
    std::filesystem::create_directories(target.parent_path(), error);
    if (error) {
      throw areagraph::InputError("cannot create the folder '" + target.parent_path().string() +
                                  "': " + error.message());
    }
    areagraph::WriteOutputFile(target.string(), areagraph::ExportAreaGraph(graph, settings));
    std::cout << "wrote " << target.string() << "\n";
  }
  if (missing.empty()) return 0;
  std::cerr << "ag-export: " << missing.size() << " of " << maps.size()
            << " maps have no Area Graph (run ag-merge first): " << Join(missing, ", ") << "\n";
  return 1;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{
      "Writes the Area Graph of one map (or, with --all, of every map) in another format.\n"
      "  labels     16-bit PNG the size of the map: 0 = no area, area id + 1 inside each area\n"
      "  kinds      TSV of each label's kind (room, corridor, dead_end), for ag-eval\n"
      "  preview    colour PNG to look at: areas filled, passages red\n"
      "  geojson    FeatureCollection (ids area/<id>, passage/<id>): WGS 84 with --anchor-lat/\n"
      "             --anchor-lon, else local map metres (the file says which); QGIS, GDAL\n"
      "  osmag      osmAG XML (the Area Graph authors' OSM format) for JOSM: areas as closed\n"
      "             ways under a structure area, passages as ways over nodes of both areas\n"
      "  json       networkx node-link JSON: nx.node_link_graph(json.load(f)) is a MultiGraph\n"
      "  protojson  the AreaGraph message as protobuf JSON\n"
      "  html       one self-contained page to inspect every stage in a browser (layers, hover,\n"
      "             zoom, options, times); --compare KEY shows a second run beside it"};
  std::string store_path = "areagraph.db", map_name, format_name, out_path, key, compare_key;
  std::string features = "all";
  areagraph::GeoAnchor anchor;
  areagraph::ExportSettings settings;
  app.add_option("--store", store_path, "SQLite artifact store")->capture_default_str();
  bool all_maps = false;
  auto* map_option = app.add_option("--map", map_name, "name of the map in the store");
  app.add_flag("--all", all_maps,
               "every map of the store, each into the folder --out as <map> + .png (labels), "
               ".kinds.tsv, .preview.png, .geojson, .osm, .json or .pb.json (protojson); exit "
               "status 1 when a map has no Area Graph")
      ->excludes(map_option);
  app.add_option("--format", format_name,
                 "labels, kinds, preview, geojson, osmag, json, protojson or html")
      ->required();
  app.add_option("--out", out_path,
                 "file to write, or - for standard output; with --all, the folder to write into")
      ->required();
  app.add_option("--anchor-lat", anchor.lat_deg,
                 "geojson, osmag: latitude of the map's world origin in degrees (osmag without "
                 "it: 31.17947)");
  app.add_option("--anchor-lon", anchor.lon_deg,
                 "geojson, osmag: longitude of the map's world origin in degrees (osmag without "
                 "it: 121.59042)");
  app.add_option("--level", settings.level, "osmag: the floor, tagged level")
      ->capture_default_str();
  app.add_option("--height", settings.height_m,
                 "osmag: the floor's height in metres, tagged height on every area (default: "
                 "unknown, not written)");
  app.add_option("--features", features,
                 "geojson: all, areas or passages (one geometry type per file, as Shapefile "
                 "needs)")
      ->capture_default_str();
  app.add_option("--key", key,
                 "html: show the run behind this artifact key (prefix; default: heads)");
  app.add_option("--compare", compare_key, "html: a second key of the map to compare with");
  return areagraph::RunCommand("ag-export", app, argc, argv, [&] {
    if (!all_maps && map_name.empty()) {
      throw areagraph::OptionsError("give --map NAME, or --all for every map of the store");
    }
    if (format_name == "html") {
      if (all_maps) {
        throw areagraph::OptionsError(
            "--all does not go with --format html (ag-run --report DIR writes every map's page)");
      }
      const int status =
          areagraph::ExportViewerPage(store_path, map_name, key, compare_key, out_path);
      if (status == 0 && !areagraph::IsStandardOutput(out_path)) {
        std::cout << "wrote " << out_path << "\n";
      }
      return status;
    }
    if (!key.empty() || !compare_key.empty()) {
      throw areagraph::OptionsError("--key and --compare go with --format html");
    }
    RequireFormatFor(app, format_name, {"osmag"}, {"--level", "--height"});
    RequireFormatFor(app, format_name, {"geojson"}, {"--features"});
    RequireFormatFor(app, format_name, {"geojson", "osmag"}, {"--anchor-lat", "--anchor-lon"});
    settings.format = areagraph::ParseExportFormat(format_name);
    settings.map_name = map_name;
    settings.features = areagraph::ParseGeoJsonFeatures(features);
    if (app.count("--anchor-lat") != app.count("--anchor-lon")) {
      throw areagraph::OptionsError("give both --anchor-lat and --anchor-lon, or neither");
    }
    areagraph::CheckGeoAnchor(anchor);
    if (app.count("--anchor-lat") > 0) settings.anchor = anchor;
    if (!(settings.height_m >= 0 && settings.height_m <= areagraph::kMaxOptionLengthM)) {
      throw areagraph::OptionsError("--height must be a number of metres in [0, " +
                                    areagraph::FormatNumber(areagraph::kMaxOptionLengthM) + "]");
    }
    auto store = areagraph::OpenArtifactStore(store_path, areagraph::StoreMode::kReadOnly);
    if (all_maps) return ExportEveryMap(*store, settings, store_path, out_path);
    const std::optional<std::string> graph_key = areagraph::NewestGraphKey(*store, map_name);
    if (!graph_key) {
      throw areagraph::InputError(
          store->ReadMap(map_name) ? "map '" + map_name + "' has no Area Graph; run ag-merge first"
                                   : "map '" + map_name + "' is not in the store");
    }
    const auto graph =
        areagraph::ReadArtifactAs<areagraph::proto::AreaGraph>(*store, map_name, *graph_key);
    areagraph::WriteOutputFile(out_path, areagraph::ExportAreaGraph(graph, settings));
    if (!areagraph::IsStandardOutput(out_path)) std::cout << "wrote " << out_path << "\n";
    return 0;
  });
}

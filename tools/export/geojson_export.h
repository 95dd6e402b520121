#pragma once

#include <optional>
#include <string>

#include "proto/artifacts.pb.h"
#include "tools/export/geo_anchor.h"

namespace areagraph {

// Which features a GeoJSON file holds: GIS formats such as Shapefile take one
// geometry type per layer, so areas and passages can go to separate files.
enum class GeoJsonFeatures { kAll, kAreas, kPassages };

// "all", "areas" or "passages"; throws OptionsError otherwise.
GeoJsonFeatures ParseGeoJsonFeatures(const std::string& name);

struct GeoJsonSettings {
  std::string map_name;
  // With an anchor the coordinates are WGS 84 longitude, latitude (RFC 7946);
  // without, world metres of the map frame.
  std::optional<GeoAnchor> anchor;
  GeoJsonFeatures features = GeoJsonFeatures::kAll;
};

// The Area Graph as a GeoJSON FeatureCollection, with ids from ExportIds
// (the stable ids of a graph from ag-match, else the indices). Top-level
// members besides the features: name (the map; GDAL takes it as the layer
// name), ids ("stable" or "index": which ids the file holds), frame (the
// map's MapFrame), units ("degrees" or "metres"), coordinates (one sentence
// saying which; without an anchor that the file is NOT WGS 84 although GIS
// tools will assume so), anchor when given, and without an anchor a crs
// member (GeoJSON 2008) naming the map frame as a local engineering CRS in
// WKT, which GDAL and QGIS honour. Metres are written to the millimetre,
// degrees to 8 decimals. One feature per line, each with an id unique in
// the file:
// - each area "area/<id>", a Polygon: closed outer ring counter-clockwise,
//   closed holes clockwise (RFC 7946 winding); properties layer ("area"),
//   area_id (<id>), stable_id (graphs from ag-match), index (in this
//   version), kind (room, corridor, dead_end), area_m2, name (area_<id>);
// - each passage "passage/<id>", a LineString along border_m, the border its
//   two areas share (whose points are vertices of both polygons), or along
//   segment_m when it has none; properties layer ("passage"), passage_id,
//   stable_id, index (as for areas), kind ("passage"), width_m, from and to
//   (area ids).
// Areas come first. Throws InputError for coordinates that are not finite.
std::string AreaGraphToGeoJson(const proto::AreaGraph& graph, const GeoJsonSettings& settings);

}  // namespace areagraph

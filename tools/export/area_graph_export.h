#pragma once

#include <optional>
#include <string>

#include "proto/artifacts.pb.h"
#include "tools/export/geo_anchor.h"
#include "tools/export/geojson_export.h"

namespace areagraph {

enum class ExportFormat {
  // 16-bit PNG label image (see area_label_image.h).
  kLabels,
  // The kind of each label of kLabels: "label<TAB>kind" lines under that
  // header (ag-eval reads it beside the label image).
  kKinds,
  // Colour PNG for people (see preview_image.h).
  kPreview,
  // GeoJSON (see geojson_export.h).
  kGeoJson,
  // osmAG XML (see osmag_export.h).
  kOsmAg,
  // networkx node-link JSON (see node_link_json.h).
  kJson,
  // The AreaGraph message as protobuf JSON, which reads back losslessly.
  kProtoJson,
};

// "labels", "kinds", "preview", "geojson", "osmag", "json" or "protojson"; throws
// OptionsError otherwise.
ExportFormat ParseExportFormat(const std::string& name);

// What a map's file of this format ends with when ag-export --all names it:
// ".png" for labels and ".kinds.tsv" for kinds, the names ag-eval --dataset
// pairs; ".preview.png", ".geojson", ".osm", ".json" and ".pb.json" else.
std::string ExportFileSuffix(ExportFormat format);

struct ExportSettings {
  ExportFormat format = ExportFormat::kJson;
  std::string map_name;
  // Where the map's origin lies on the globe: GeoJSON is WGS 84 with it and
  // metres without; osmAG uses GeoAnchor's default without.
  std::optional<GeoAnchor> anchor;
  // osmAG only: the floor and its height (0 = unknown).
  int level = 0;
  double height_m = 0;
  // GeoJSON only: which features to write.
  GeoJsonFeatures features = GeoJsonFeatures::kAll;
};

// The bytes of the export file.
std::string ExportAreaGraph(const proto::AreaGraph& graph, const ExportSettings& settings);

// kKinds' text.
std::string AreaKindsTsv(const proto::AreaGraph& graph);

// protobuf's JSON printer (field names as in the .proto, indented).
std::string AreaGraphToJson(const proto::AreaGraph& graph);

}  // namespace areagraph

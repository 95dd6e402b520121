#pragma once

#include <string>

#include "proto/artifacts.pb.h"
#include "tools/export/osmag_export.h"

namespace areagraph {

enum class ExportFormat {
  // 16-bit PNG label image (see area_label_image.h).
  kLabels,
  // GeoJSON in world metres (see geojson_export.h).
  kGeoJson,
  // osmAG XML (see osmag_export.h).
  kOsmAg,
  // The AreaGraph message as protobuf JSON.
  kJson,
};

// "labels", "geojson", "osmag" or "json"; throws OptionsError otherwise.
ExportFormat ParseExportFormat(const std::string& name);

struct ExportSettings {
  ExportFormat format = ExportFormat::kJson;
  // Used by osmAG only.
  std::string map_name;
  GeoAnchor anchor;
};

// The bytes of the export file.
std::string ExportAreaGraph(const proto::AreaGraph& graph, const ExportSettings& settings);

// protobuf's JSON printer (field names as in the .proto, indented).
std::string AreaGraphToJson(const proto::AreaGraph& graph);

}  // namespace areagraph

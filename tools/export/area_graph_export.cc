#include "tools/export/area_graph_export.h"

#include <google/protobuf/util/json_util.h>

#include <opencv2/imgcodecs.hpp>
#include <vector>

#include "common/error.h"
#include "stages/common/png_file.h"
#include "tools/export/area_label_image.h"
#include "tools/export/area_polygons.h"
#include "tools/export/node_link_json.h"
#include "tools/export/osmag_export.h"
#include "tools/export/preview_image.h"

namespace areagraph {

ExportFormat ParseExportFormat(const std::string& name) {
  if (name == "labels") return ExportFormat::kLabels;
  if (name == "kinds") return ExportFormat::kKinds;
  if (name == "preview") return ExportFormat::kPreview;
  if (name == "geojson") return ExportFormat::kGeoJson;
  if (name == "osmag") return ExportFormat::kOsmAg;
  if (name == "json") return ExportFormat::kJson;
  if (name == "protojson") return ExportFormat::kProtoJson;
  throw OptionsError("unknown export format '" + name +
                     "'; use labels, kinds, preview, geojson, osmag, json, protojson or html");
}

std::string ExportFileSuffix(ExportFormat format) {
  switch (format) {
    case ExportFormat::kLabels:
      return ".png";
    case ExportFormat::kKinds:
      return ".kinds.tsv";
    case ExportFormat::kPreview:
      return ".preview.png";
    case ExportFormat::kGeoJson:
      return ".geojson";
    case ExportFormat::kOsmAg:
      return ".osm";
    case ExportFormat::kJson:
      return ".json";
    case ExportFormat::kProtoJson:
      return ".pb.json";
  }
  return ".out";
}

std::string AreaKindsTsv(const proto::AreaGraph& graph) {
  std::string tsv = "label\tkind\n";
  for (const proto::Area& area : graph.areas()) {
    tsv += std::to_string(area.id() + 1) + "\t" + AreaKindName(area.kind()) + "\n";
  }
  return tsv;
}

std::string AreaGraphToJson(const proto::AreaGraph& graph) {
  google::protobuf::util::JsonPrintOptions options;
  options.add_whitespace = true;
  options.preserve_proto_field_names = true;
  std::string json;
  if (!google::protobuf::util::MessageToJsonString(graph, &json, options).ok()) {
    throw Error("cannot print the Area Graph as JSON");
  }
  return json;
}

std::string ExportAreaGraph(const proto::AreaGraph& graph, const ExportSettings& settings) {
  switch (settings.format) {
    case ExportFormat::kLabels:
      return EncodePng(AreaLabelImage(graph), /*compression=*/1);
    case ExportFormat::kKinds:
      return AreaKindsTsv(graph);
    case ExportFormat::kPreview:
      return EncodePng(AreaGraphPreview(graph), /*compression=*/1);
    case ExportFormat::kGeoJson:
      return AreaGraphToGeoJson(graph, {settings.map_name, settings.anchor, settings.features});
    case ExportFormat::kOsmAg:
      return AreaGraphToOsmAg(graph, {settings.map_name, settings.anchor.value_or(GeoAnchor()),
                                      settings.level, settings.height_m});
    case ExportFormat::kJson:
      return AreaGraphToNodeLinkJson(graph, settings.map_name);
    case ExportFormat::kProtoJson:
      return AreaGraphToJson(graph);
  }
  throw OptionsError("unknown export format");
}

}  // namespace areagraph

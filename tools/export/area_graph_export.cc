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

namespace {

// Each format's name (--format) and the end of its file's name (--all).
struct FormatName {
  ExportFormat format;
  const char* name;
  const char* suffix;
};
constexpr FormatName kFormatNames[] = {
    {ExportFormat::kLabels, "labels", ".png"},
    {ExportFormat::kKinds, "kinds", ".kinds.tsv"},
    {ExportFormat::kPreview, "preview", ".preview.png"},
    {ExportFormat::kGeoJson, "geojson", ".geojson"},
    {ExportFormat::kOsmAg, "osmag", ".osm"},
    {ExportFormat::kJson, "json", ".json"},
    {ExportFormat::kProtoJson, "protojson", ".pb.json"},
};

}  // namespace

ExportFormat ParseExportFormat(const std::string& name) {
  for (const FormatName& entry : kFormatNames) {
    if (name == entry.name) return entry.format;
  }
  throw OptionsError("unknown export format '" + name +
                     "'; use labels, kinds, preview, geojson, osmag, json, protojson or html");
}

std::string ExportFileSuffix(ExportFormat format) {
  for (const FormatName& entry : kFormatNames) {
    if (format == entry.format) return entry.suffix;
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

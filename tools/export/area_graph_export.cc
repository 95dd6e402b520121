#include "tools/export/area_graph_export.h"

#include <google/protobuf/util/json_util.h>

#include <opencv2/imgcodecs.hpp>
#include <vector>

#include "common/error.h"
#include "stages/common/png_file.h"
#include "tools/export/area_label_image.h"
#include "tools/export/geojson_export.h"

namespace areagraph {

ExportFormat ParseExportFormat(const std::string& name) {
  if (name == "labels") return ExportFormat::kLabels;
  if (name == "geojson") return ExportFormat::kGeoJson;
  if (name == "osmag") return ExportFormat::kOsmAg;
  if (name == "json") return ExportFormat::kJson;
  throw OptionsError("unknown export format '" + name +
                     "'; use labels, geojson, osmag, json or html");
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
    case ExportFormat::kGeoJson:
      return AreaGraphToGeoJson(graph);
    case ExportFormat::kOsmAg:
      return AreaGraphToOsmAg(graph, settings.map_name, settings.anchor);
    case ExportFormat::kJson:
      return AreaGraphToJson(graph);
  }
  throw OptionsError("unknown export format");
}

}  // namespace areagraph

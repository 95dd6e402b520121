#include "tools/export/area_graph_export.h"

#include <google/protobuf/util/json_util.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <opencv2/imgcodecs.hpp>
#include <vector>

#include "common/error.h"
#include "tools/export/area_label_image.h"
#include "tools/export/node_link_json.h"
#include "tools/export/osmag_export.h"
#include "tools/export/preview_image.h"

namespace areagraph {

ExportFormat ParseExportFormat(const std::string& name) {
  if (name == "labels") return ExportFormat::kLabels;
  if (name == "preview") return ExportFormat::kPreview;
  if (name == "geojson") return ExportFormat::kGeoJson;
  if (name == "osmag") return ExportFormat::kOsmAg;
  if (name == "json") return ExportFormat::kJson;
  if (name == "protojson") return ExportFormat::kProtoJson;
  throw OptionsError("unknown export format '" + name +
                     "'; use labels, preview, geojson, osmag, json, protojson or html");
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

namespace {

std::string EncodePng(const cv::Mat& image) {
  std::vector<uchar> bytes;
  if (!cv::imencode(".png", image, bytes)) throw Error("cannot encode the image as PNG");
  return std::string(bytes.begin(), bytes.end());
}

}  // namespace

std::string ExportAreaGraph(const proto::AreaGraph& graph, const ExportSettings& settings) {
  switch (settings.format) {
    case ExportFormat::kLabels:
      return EncodePng(AreaLabelImage(graph));
    case ExportFormat::kPreview:
      return EncodePng(AreaGraphPreview(graph));
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

void WriteExportFile(const std::string& path, const std::string& bytes) {
  namespace fs = std::filesystem;
  std::error_code error;
  if (fs::is_directory(path, error))
    throw InputError("cannot write '" + path + "': it is a folder");
  const std::string temporary = path + ".tmp";
  {
    std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    out.close();
    if (!out) {
      fs::remove(temporary, error);
      throw InputError("cannot write '" + path + "' (missing folder or no permission?)");
    }
  }
  fs::rename(temporary, path, error);
  if (error) {
    fs::remove(temporary, error);
    throw InputError("cannot write '" + path + "': " + error.message());
  }
}

}  // namespace areagraph

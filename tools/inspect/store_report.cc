#include "tools/inspect/store_report.h"

#include <cstdio>
#include <memory>

#include <google/protobuf/util/json_util.h>

#include "proto/artifacts.pb.h"
#include "stages/common/artifact_types.h"
#include "stages/common/grid_cells.h"
#include "store/error.h"

namespace areagraph {
namespace {

std::string ShortKey(const std::string& key) { return key.substr(0, 12); }

std::unique_ptr<google::protobuf::Message> ParseArtifact(const ArtifactRecord& artifact) {
  std::unique_ptr<google::protobuf::Message> message = NewArtifactMessage(artifact.proto_type);
  if (!message) {
    throw StoreError("artifact " + ShortKey(artifact.cache_key) + " has type '" +
                     artifact.proto_type + "', unknown to this build");
  }
  if (!message->ParseFromString(artifact.payload)) {
    throw StoreError("artifact " + ShortKey(artifact.cache_key) + " does not parse as " +
                     artifact.proto_type);
  }
  return message;
}

void PrintFrame(const proto::MapFrame& frame, std::ostream& out) {
  char line[200];
  std::snprintf(line, sizeof(line), "frame: %dx%d px, %.4g m/px, origin (%.3f, %.3f, %.3f rad)\n",
                frame.width_px(), frame.height_px(), frame.resolution_m(), frame.origin_x_m(),
                frame.origin_y_m(), frame.origin_yaw_rad());
  out << line;
}

void PrintCells(const std::string& cells, std::ostream& out) {
  const CellCounts counts = CountCells(cells);
  out << "cells: " << counts.occupied << " occupied, " << counts.free << " free, "
      << counts.unknown << " unknown\n";
}

}  // namespace

void PrintMapList(ArtifactStore& store, std::ostream& out) {
  const std::vector<MapRecord> maps = store.ReadAllMaps();
  if (maps.empty()) {
    out << "no maps in the store; add one with ag-import\n";
    return;
  }
  char line[512];
  std::snprintf(line, sizeof(line), "%-32s %9s  %s\n", "map", "artifacts", "source");
  out << line;
  for (const MapRecord& map : maps) {
    const size_t artifacts = store.ReadArtifactSummaries(map.name).size();
    std::snprintf(line, sizeof(line), "%-32s %9zu  %s\n", map.name.c_str(), artifacts,
                  map.source_path.c_str());
    out << line;
  }
}

void PrintArtifactList(ArtifactStore& store, const std::string& map_name, std::ostream& out) {
  if (!store.ReadMap(map_name)) throw InputError("map '" + map_name + "' is not in the store");
  char line[512];
  std::snprintf(line, sizeof(line), "%-8s %-12s %10s %10s  %-20s %s\n", "stage", "key", "bytes",
                "ms", "created (UTC)", "head");
  out << line;
  for (const ArtifactRecord& artifact : store.ReadArtifactSummaries(map_name)) {
    std::snprintf(line, sizeof(line), "%-8s %-12s %10lld %10.1f  %-20s %s\n",
                  artifact.stage.c_str(), ShortKey(artifact.cache_key).c_str(),
                  static_cast<long long>(artifact.payload_bytes), artifact.elapsed_ms,
                  artifact.created_at.c_str(), artifact.is_head ? "*" : "");
    out << line;
  }
}

ArtifactRecord FindArtifact(ArtifactStore& store, const std::string& map_name,
                            const std::string& stage, const std::string& key_prefix) {
  if (!store.ReadMap(map_name)) throw InputError("map '" + map_name + "' is not in the store");
  if (key_prefix.empty()) {
    std::optional<ArtifactRecord> head = store.ReadHead(map_name, stage);
    if (!head) throw InputError("map '" + map_name + "' has no " + stage + " artifact");
    return *head;
  }
  std::string found;
  for (const ArtifactRecord& artifact : store.ReadArtifactSummaries(map_name)) {
    if (artifact.cache_key.compare(0, key_prefix.size(), key_prefix) != 0) continue;
    if (!stage.empty() && artifact.stage != stage) continue;
    if (!found.empty() && found != artifact.cache_key) {
      throw InputError("key prefix '" + key_prefix + "' matches several artifacts of map '" +
                       map_name + "'; give more digits");
    }
    found = artifact.cache_key;
  }
  if (found.empty()) {
    throw InputError("map '" + map_name + "' has no artifact with key '" + key_prefix + "'");
  }
  return *store.ReadArtifact(map_name, found);
}

void PrintArtifactSummary(const ArtifactRecord& artifact, std::ostream& out) {
  out << "map: " << artifact.map_name << "\nstage: " << artifact.stage << " (version "
      << artifact.stage_version << ")\nkey: " << artifact.cache_key
      << "\ntype: " << artifact.proto_type << "\nbytes: " << artifact.payload_bytes
      << "\ncreated: " << artifact.created_at << "\nelapsed: " << artifact.elapsed_ms << " ms\n";
  const std::unique_ptr<google::protobuf::Message> message = ParseArtifact(artifact);
  if (const auto* grid = dynamic_cast<const proto::GridMap*>(message.get())) {
    PrintFrame(grid->frame(), out);
    PrintCells(grid->cells(), out);
    out << "source: " << grid->source_path() << " (sha256 " << grid->source_digest() << ")\n";
  } else if (const auto* cleaned = dynamic_cast<const proto::CleanedMap*>(message.get())) {
    PrintFrame(cleaned->frame(), out);
    PrintCells(cleaned->cells(), out);
    out << "removed: " << cleaned->removed_outlier_cells_size() << " outlier cells, "
        << cleaned->removed_furniture_cells_size() << " furniture cells\n";
  } else if (const auto* voronoi = dynamic_cast<const proto::VoronoiDiagram*>(message.get())) {
    out << "voronoi: " << voronoi->sites_size() << " sites, " << voronoi->vertices_size()
        << " vertices, " << voronoi->edges_size() << " edges\n";
  } else if (const auto* topology = dynamic_cast<const proto::TopologyGraph*>(message.get())) {
    out << "topology graph: " << topology->vertices_size() << " vertices, "
        << topology->edges_size() << " edges\n";
  } else if (const auto* cut = dynamic_cast<const proto::CutGraph*>(message.get())) {
    out << "cut graph: " << cut->room_shapes_size() << " rooms, " << cut->edges_size()
        << " edges, " << cut->passage_points_size() << " passage points\n";
  } else if (const auto* areas = dynamic_cast<const proto::AreaGraph*>(message.get())) {
    out << "area graph: " << areas->areas_size() << " areas, " << areas->passages_size()
        << " passages\n";
  }
  out << "options:\n" << artifact.options_text;
}

void PrintArtifactJson(const ArtifactRecord& artifact, std::ostream& out) {
  const std::unique_ptr<google::protobuf::Message> message = ParseArtifact(artifact);
  google::protobuf::util::JsonPrintOptions options;
  options.add_whitespace = true;
  options.preserve_proto_field_names = true;
  std::string json;
  const auto status = google::protobuf::util::MessageToJsonString(*message, &json, options);
  if (!status.ok()) throw StoreError("cannot print artifact as JSON: " + status.ToString());
  out << json;
}

}  // namespace areagraph

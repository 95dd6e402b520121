#include "tools/inspect/store_report.h"

#include <cstdio>
#include <memory>
#include <optional>
#include <utility>

#include "common/error.h"
#include "common/json.h"
#include "common/text.h"
#include "proto/artifacts.pb.h"
#include "stages/pipeline/stage.h"
#include "stages/pipeline/stage_table.h"
#include "tools/inspect/failure_report.h"

namespace areagraph {
namespace {

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
  CheckFormatVersion(*message, "artifact " + ShortKey(artifact.cache_key));
  return message;
}

// The frame that every artifact message carries in its `frame` field.
const proto::MapFrame* FrameOf(const google::protobuf::Message& artifact) {
  const google::protobuf::FieldDescriptor* field =
      artifact.GetDescriptor()->FindFieldByName("frame");
  if (field == nullptr || field->message_type() != proto::MapFrame::descriptor()) return nullptr;
  return static_cast<const proto::MapFrame*>(
      &artifact.GetReflection()->GetMessage(artifact, field));
}

void PrintFrame(const proto::MapFrame& frame, std::ostream& out) {
  char line[200];
  std::snprintf(line, sizeof(line), "frame: %dx%d px, %.4g m/px, origin (%.3f, %.3f, %.3f rad)\n",
                frame.width_px(), frame.height_px(), frame.resolution_m(), frame.origin_x_m(),
                frame.origin_y_m(), frame.origin_yaw_rad());
  out << line;
}

}  // namespace

void PrintMapList(ArtifactStore& store, std::ostream& out) {
  const std::vector<MapRecord> maps = store.ReadAllMaps();
  if (maps.empty()) {
    out << "no maps in the store; add one with ag-import\n";
    PrintFailedMapsNote(store.ReadFailures(), out);  // e.g. every import failed
    return;
  }
  char line[512];
  std::snprintf(line, sizeof(line), "%-32s %9s  %s\n", "map", "artifacts", "source");
  out << line;
  for (const MapRecord& map : maps) {
    std::snprintf(line, sizeof(line), "%-32s %9lld  %s\n", map.name.c_str(),
                  static_cast<long long>(store.CountArtifacts(map.name)), map.source_path.c_str());
    out << line;
  }
  PrintFailedMapsNote(store.ReadFailures(), out);
}

void PrintArtifactList(ArtifactStore& store, const std::string& map_name, std::ostream& out) {
  std::optional<FailureRecord> failure;
  for (FailureRecord& recorded : store.ReadFailures()) {
    if (recorded.map_name == map_name) failure = std::move(recorded);
  }
  const auto print_failure = [&] {
    if (!failure) return;
    out << "failed in " << failure->stage << " at " << failure->failed_at << ": "
        << failure->message << "\n";
  };
  if (!store.ReadMap(map_name)) {
    if (!failure) throw InputError("map '" + map_name + "' is not in the store");
    out << "map '" << map_name << "' has no artifacts; it ";
    return print_failure();
  }
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
  print_failure();
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

// The parts of the map kept (-1: not known here) and those dropped as
// smaller than prune.min_component_m2.
static void PrintParts(int kept, int dropped, double dropped_area_m2, std::ostream& out) {
  if (kept >= 0) out << "parts: " << kept << " kept";
  out << (kept >= 0 ? ", " : "parts: ") << dropped << " dropped";
  if (dropped > 0) out << " (" << dropped_area_m2 << " m2 of free space)";
  out << " (prune.min_component_m2)\n";
}

// W and, when it was estimated, the doors and corridors behind it.
static void PrintRoomWidth(const proto::RoomWidthEstimate& estimate, std::ostream& out) {
  out << "room width W: " << estimate.room_width_m() << " m"
      << (estimate.automatic() ? " (auto)" : "") << "\n";
  if (!estimate.automatic()) return;
  out << "widest door: " << estimate.widest_door_m()
      << " m, narrowest corridor: " << estimate.narrowest_corridor_m() << " m\n";
  for (const proto::DetectedWidth& door : estimate.doors()) {
    out << "  door " << door.width_m() << " m at (" << door.position().x() << ", "
        << door.position().y() << ") px\n";
  }
  for (const proto::DetectedWidth& corridor : estimate.corridors()) {
    out << "  corridor " << corridor.width_m() << " m, " << corridor.length_m() << " m long, at ("
        << corridor.position().x() << ", " << corridor.position().y() << ") px\n";
  }
}

void PrintArtifactSummary(const ArtifactRecord& artifact, std::ostream& out) {
  out << "map: " << artifact.map_name << "\nstage: " << artifact.stage << " (version "
      << artifact.stage_version << ")\nkey: " << artifact.cache_key
      << "\ntype: " << artifact.proto_type << "\nbytes: " << artifact.payload_bytes
      << "\ncreated: " << artifact.created_at << "\nelapsed: " << artifact.elapsed_ms << " ms\n";
  const std::unique_ptr<google::protobuf::Message> message = ParseArtifact(artifact);
  out << "summary: " << SummarizeArtifact(*message) << "\n";
  if (const proto::MapFrame* frame = FrameOf(*message)) PrintFrame(*frame, out);
  // What only one type has, beyond its summary.
  if (const auto* grid = dynamic_cast<const proto::GridMap*>(message.get())) {
    out << "source: " << grid->source_path() << " (sha256 " << grid->source_digest() << ")\n";
  } else if (const auto* topology = dynamic_cast<const proto::TopologyGraph*>(message.get())) {
    PrintParts(topology->parts(), topology->dropped_parts(), topology->dropped_area_m2(), out);
  } else if (const auto* cut = dynamic_cast<const proto::CutGraph*>(message.get())) {
    PrintParts(cut->parts(), cut->dropped_parts(), cut->dropped_area_m2(), out);
    PrintRoomWidth(cut->room_width(), out);
  } else if (const auto* areas = dynamic_cast<const proto::AreaGraph*>(message.get())) {
    out << "components: " << areas->components() << " (areas joined by passages)\n";
    PrintParts(-1, areas->dropped_parts(), areas->dropped_area_m2(), out);
  }
  out << "options:\n" << artifact.options_text;
}

void PrintArtifactJson(const ArtifactRecord& artifact, std::ostream& out) {
  out << MessageToJson(*ParseArtifact(artifact));
}

}  // namespace areagraph

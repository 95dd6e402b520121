#include "tools/export/viewer_run.h"

#include <map>
#include <set>

#include "common/error.h"
#include "common/text.h"
#include "proto/artifacts.pb.h"
#include "stages/pipeline/stage.h"
#include "tools/export/svg_path.h"
#include "tools/export/viewer_layers.h"
#include "tools/export/viewer_options.h"
#include "tools/export/viewer_route_layer.h"
#include "tools/inspect/store_report.h"

namespace areagraph {
namespace {

// The head of the latest stage that the map has.
ArtifactRecord NewestStageHead(ArtifactStore& store, const std::string& map_name) {
  const std::vector<StageDefinition>& stages = StageTable();
  for (auto stage = stages.rbegin(); stage != stages.rend(); ++stage) {
    std::optional<ArtifactRecord> head = store.ReadHead(map_name, stage->info.name);
    if (head) return *head;
  }
  throw InputError("map '" + map_name + "' has no artifacts");
}

// The artifact's payload as T; throws StoreError when it is not one, or is
// of a format newer than this build.
template <typename T>
T Parse(const ArtifactRecord& artifact) {
  T message;
  const std::string what = "the " + artifact.stage + " artifact " + ShortKey(artifact.cache_key) +
                           " of map '" + artifact.map_name + "'";
  if (artifact.proto_type != message.GetTypeName() || !message.ParseFromString(artifact.payload)) {
    throw StoreError(what + " is not a valid " + message.GetTypeName());
  }
  CheckFormatVersion(message, what);
  return message;
}

// The panel's record of one artifact: key, time, options.
viewer::StageRecord RecordOf(const ArtifactRecord& artifact) {
  viewer::StageRecord record;
  record.set_stage(artifact.stage);
  record.set_cache_key(artifact.cache_key);
  record.set_stage_version(artifact.stage_version);
  record.set_elapsed_ms(Rounded(artifact.elapsed_ms, 1));
  record.set_created_at(artifact.created_at);
  record.set_payload_bytes(static_cast<int32_t>(artifact.payload_bytes));
  for (const viewer::OptionValue& value :
       StageOptionValues(artifact.stage, artifact.options_text)) {
    *record.add_options() = value;
  }
  return record;
}

// Whether the diff view's first run holds the artifact with `key` already.
bool FirstHasKey(const viewer::Run* first, const std::string& key) {
  if (first == nullptr) return false;
  for (const viewer::StageRecord& stage : first->stages()) {
    if (stage.cache_key() == key) return true;
  }
  return false;
}

// Fills the layer of one artifact's stage.
void AddLayer(const ArtifactRecord& artifact, const ArtifactRecord* grid_artifact,
              viewer::Run* run) {
  const std::string& stage = artifact.stage;
  if (stage == kImportStage.name) {
    run->set_grid_png(GridMapPng(Parse<proto::GridMap>(artifact)));
  } else if (stage == kCleanStage.name) {
    const auto cleaned = Parse<proto::CleanedMap>(artifact);
    if (grid_artifact != nullptr) {
      const auto grid = Parse<proto::GridMap>(*grid_artifact);
      *run->mutable_clean() = CleanLayerOf(cleaned, &grid);
    } else {
      *run->mutable_clean() = CleanLayerOf(cleaned, nullptr);
    }
  } else if (stage == kVoronoiStage.name) {
    *run->mutable_voronoi() = VoronoiLayerOf(Parse<proto::VoronoiDiagram>(artifact));
  } else if (stage == kPruneStage.name) {
    *run->mutable_topology() = TopologyLayerOf(Parse<proto::TopologyGraph>(artifact));
  } else if (stage == kCutStage.name) {
    const auto cut = Parse<proto::CutGraph>(artifact);
    *run->mutable_cut() = CutLayerOf(cut);
    proto::CutOptions options;
    ParseStageOptions(stage, artifact.options_text, &options);
    *run->mutable_room_width() = RoomWidthOf(cut.room_width(), options);
  } else if (stage == kMergeStage.name || stage == kMatchStage.name) {
    // Match comes after merge: its graph (stable ids, noise pieces folded
    // back) is the one published, and replaces merge's.
    const auto graph = Parse<proto::AreaGraph>(artifact);
    *run->mutable_area_graph() = AreaLayerOf(graph);
    SetRouteGraph(graph, run);
  }
}

}  // namespace

std::vector<ArtifactRecord> RunArtifacts(ArtifactStore& store, const std::string& map_name,
                                         const std::string& key_prefix) {
  if (!store.ReadMap(map_name)) throw InputError("map '" + map_name + "' is not in the store");
  std::map<std::string, ArtifactRecord> by_stage;
  std::vector<ArtifactRecord> pending = {key_prefix.empty()
                                             ? NewestStageHead(store, map_name)
                                             : FindArtifact(store, map_name, "", key_prefix)};
  std::set<std::string> seen;
  while (!pending.empty()) {
    ArtifactRecord artifact = std::move(pending.back());
    pending.pop_back();
    if (!seen.insert(artifact.cache_key).second || by_stage.count(artifact.stage)) continue;
    // An import's input is the file's digest, not an artifact.
    if (artifact.stage != kImportStage.name) {
      for (const std::string& input : artifact.input_keys) {
        std::optional<ArtifactRecord> found = store.ReadArtifact(map_name, input);
        if (found) pending.push_back(std::move(*found));  // a collected one is just absent
      }
    }
    std::string stage = artifact.stage;
    by_stage.emplace(stage, std::move(artifact));
  }
  std::vector<ArtifactRecord> ordered;
  for (const StageDefinition& stage : StageTable()) {
    auto found = by_stage.find(stage.info.name);
    if (found != by_stage.end()) ordered.push_back(std::move(found->second));
  }
  return ordered;
}

viewer::Run ViewerRunOf(const std::vector<ArtifactRecord>& artifacts, const std::string& label,
                        const viewer::Run* first) {
  viewer::Run run;
  run.set_label(label);
  const ArtifactRecord* grid_artifact = nullptr;
  for (const ArtifactRecord& artifact : artifacts) {
    if (artifact.stage == kImportStage.name) grid_artifact = &artifact;
  }
  for (const ArtifactRecord& artifact : artifacts) {
    viewer::StageRecord* record = run.add_stages();
    *record = RecordOf(artifact);
    if (FirstHasKey(first, artifact.cache_key)) {
      record->set_same_as_first(true);
      continue;
    }
    AddLayer(artifact, grid_artifact, &run);
  }
  return run;
}

}  // namespace areagraph

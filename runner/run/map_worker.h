#pragma once

#include <functional>
#include <memory>
#include <set>
#include <string>
#include <vector>

#include "proto/artifacts.pb.h"
#include "proto/pipeline_options.pb.h"
#include "runner/run/map_collection.h"
#include "stages/common/stage.h"
#include "stages/pipeline/map_pipeline.h"
#include "store/artifact_store.h"

namespace areagraph {

// One map to run, with the options that apply to it.
struct MapTask {
  MapEntry entry;
  proto::PipelineOptions options;
};

// What ag-run does to each map.
struct RunSettings {
  std::string store_path;
  std::string first_stage = "import";  // --from / --only
  std::string last_stage = "merge";    // --only
  bool force = false;
};

struct MapResult {
  bool ok = false;
  std::string failed_stage;  // when !ok
  std::string error;         // when !ok
  int areas = 0;             // of the merge head, when merge ran
  int passages = 0;
  int components = 0;
  int dropped_parts = 0;       // smaller than prune.min_component_m2
  bool fully_cached = false;   // every stage was a hit
  bool graph_changed = false;  // the merge head is new or different
  bool published = false;
  bool failure_recorded = false;  // the store holds the failure already
};

// Called with each new or changed Area Graph (for --publish).
using GraphPublisher = std::function<void(const std::string& map_name, const std::string& cache_key,
                                          const proto::AreaGraph& graph)>;

// Runs maps one after another on one store connection. A worker process owns
// one; failures are recorded in the store and returned, never thrown.
class MapWorker {
 public:
  MapWorker(RunSettings settings, GraphPublisher publish);
  MapResult Run(const MapTask& task, const PipelineObserver& observer);

 private:
  ArtifactStore& Store();
  // Without --from/--only/--force: every key is computed from the source and
  // the options, and when all are stored the heads are set without any
  // artifact being read. Returns false when something must run.
  bool TryFullyCached(const MapTask& task, const std::string& import_key,
                      const PipelineObserver& observer);
  void RunStages(const MapTask& task, const PipelineObserver& observer, std::string* stage);
  void RecordFailure(const MapTask& task, MapResult& result);

  RunSettings settings_;
  GraphPublisher publish_;
  std::unique_ptr<ArtifactStore> store_;
  std::set<std::string> failed_maps_;  // recorded failures when the store was opened
};

}  // namespace areagraph

#pragma once

#include <functional>
#include <set>
#include <string>

#include "proto/artifacts.pb.h"
#include "proto/pipeline_options.pb.h"
#include "stages/pipeline/map_pipeline.h"
#include "stages/pipeline/stage.h"
#include "store/artifact_store.h"

namespace areagraph {

// Where a map's import comes from: a file for ag-run, a grid received over
// LCM for ag-live.
struct MapImport {
  // Reads the source far enough to know the digests that enter the import's
  // cache key (and the map row's source). Called once; may throw.
  std::function<StageInputs()> read_inputs;
  // The GridMap, computed only on a cache miss, after read_inputs.
  std::function<MessagePtr()> decode;
};

// Which part of the pipeline a map run covers, and how.
struct MapRunSettings {
  StageInfo first = kImportStage;  // --from, --only
  StageInfo last = kMatchStage;    // --only
  bool force = false;
  // ag-live publishes every graph it makes; ag-run only new or changed ones.
  bool publish_unchanged = false;
};

// What happened to one map.
struct MapOutcome {
  bool ok = false;
  std::string failed_step;  // a stage or "publish"; empty outside any step
  std::string error;        // the cause, without map and step
  int areas = 0;            // of the Area Graph, when the run reached it
  int passages = 0;
  int components = 0;     // of the Area Graph: parts joined by no passage
  int dropped_parts = 0;  // parts of the map smaller than prune.min_component_m2
  int stages_run = 0;
  int cache_hits = 0;
  double compute_ms = 0;
  bool fully_cached = false;   // every stage was a hit
  bool graph_changed = false;  // the Area Graph head is new or different
  bool published = false;
  bool failure_recorded = false;  // the store holds the failure
};

// Sends a map's Area Graph to live consumers.
using GraphPublisher = std::function<void(const std::string& map_name, const std::string& cache_key,
                                          const proto::AreaGraph& graph)>;

// The failures a store holds, read once, so that a map that succeeds clears
// its old failure without a write per map.
class FailureLog {
 public:
  explicit FailureLog(ArtifactStore& store);
  // Records the failure; false (never a throw) when the store cannot take it.
  bool Record(const FailureRecord& failure);
  void ClearIfRecorded(const std::string& map_name);

 private:
  ArtifactStore& store_;
  std::set<std::string> failed_maps_;
};

// Runs one map end to end, the way ag-run's workers and ag-live do: the
// import from `import`, the stages through the cache (a map whose every key
// is already stored sets its heads and reads nothing), then the Area Graph is
// published when it is new or changed, and the map's failure is recorded or
// its old one cleared. Freed heap goes back to the system between a
// compute's big steps (InputRelease::between_steps) and after the stages. A
// failure of the map is returned, never thrown.
// `observer` hears about every stage; `publish` may be empty.
MapOutcome RunOneMap(ArtifactStore& store, FailureLog& failures, const std::string& map_name,
                     const std::string& source_path, const MapImport& import,
                     const proto::PipelineOptions& options, const MapRunSettings& settings,
                     const PipelineObserver& observer, const GraphPublisher& publish);

}  // namespace areagraph

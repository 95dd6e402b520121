#pragma once

#include <memory>
#include <string>

#include "proto/pipeline_options.pb.h"
#include "runner/common/map_run.h"
#include "runner/run/map_collection.h"
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
  MapRunSettings map;
};

// Runs maps one after another on one store, opened on first use: a
// write-behind store (store/write_behind_store.h), whose thread writes each
// artifact while the next stage computes. A worker process owns one;
// failures are recorded in the store and returned, never thrown.
class MapWorker {
 public:
  MapWorker(RunSettings settings, GraphPublisher publish);
  MapOutcome Run(const MapTask& task, const PipelineObserver& observer);
  // Closes the store, which folds the write-ahead log into the
  // file: the last worker's job (ProcessPool's OnWorkerEnd), while the log's
  // index is still in its memory.
  void CloseStore();
  // Returns once the artifacts handed to the store are in it (errors are
  // left to the map's run, which reports them).
  void FinishWrites();

 private:
  RunSettings settings_;
  GraphPublisher publish_;
  std::unique_ptr<ArtifactStore> store_;
  std::unique_ptr<FailureLog> failures_;
};

}  // namespace areagraph

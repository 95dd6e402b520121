#include "runner/run/map_worker.h"

#include <exception>
#include <optional>

#include "stages/import/import_stage.h"
#include "stages/pipeline/map_pipeline.h"

namespace areagraph {

MapWorker::MapWorker(RunSettings settings, GraphPublisher publish)
    : settings_(std::move(settings)), publish_(std::move(publish)) {}

ArtifactStore& MapWorker::Store() {
  if (!store_) {
    store_ = OpenArtifactStore(settings_.store_path);
    for (const FailureRecord& failure : store_->ReadFailures()) {
      failed_maps_.insert(failure.map_name);
    }
  }
  return *store_;
}

bool MapWorker::TryFullyCached(const MapTask& task, const std::string& import_key,
                               const PipelineObserver& observer) {
  ArtifactStore& store = Store();
  const std::string& name = task.entry.name;
  std::vector<std::pair<StageInfo, std::string>> keys = {{kImportStage, import_key}};
  const std::vector<std::string> planned = PlanPipelineKeys(import_key, task.options);
  for (size_t i = 0; i < planned.size(); ++i) {
    keys.emplace_back(PipelineStages()[i], planned[i]);
  }
  for (const auto& [stage, key] : keys) {
    if (!store.HasArtifact(name, key)) return false;
  }
  for (const auto& [stage, key] : keys) {
    if (store.ReadHeadKey(name, stage.name) != key) store.UpdateHead(name, key);
    StageRun run;
    run.cache_key = key;
    run.cache_hit = true;
    if (observer.on_done) observer.on_done(stage, run);
  }
  return true;
}

void MapWorker::RunStages(const MapTask& task, const PipelineObserver& observer,
                          std::string* stage) {
  ArtifactStore& store = Store();
  const std::string& name = task.entry.name;
  const bool with_import = settings_.first_stage == kImportStage.name;
  if (with_import) {
    *stage = kImportStage.name;
    const ImportSource source = ReadImportSource(task.entry.path);
    if (!settings_.force && settings_.last_stage == kMergeStage.name &&
        TryFullyCached(task, ImportCacheKey(source, task.options.import()), observer)) {
      return;
    }
    if (observer.on_start) observer.on_start(kImportStage);
    const StageRun run =
        RunImportStage(store, name, source, task.options.import(), settings_.force);
    if (observer.on_done) observer.on_done(kImportStage, run);
    if (settings_.last_stage == kImportStage.name) return;
  }
  PipelineObserver tracking = observer;
  tracking.on_start = [&](const StageInfo& info) {
    *stage = info.name;
    if (observer.on_start) observer.on_start(info);
  };
  RunMapPipeline(store, name, task.options, settings_.force, tracking,
                 with_import ? kCleanStage.name : settings_.first_stage, settings_.last_stage);
}

MapResult MapWorker::Run(const MapTask& task, const PipelineObserver& observer) {
  MapResult result;
  const std::string& name = task.entry.name;
  std::string stage = "store";
  try {
    ArtifactStore& store = Store();
    const std::optional<std::string> old_graph = store.ReadHeadKey(name, kMergeStage.name);
    int hits = 0, runs = 0;
    PipelineObserver counting = observer;
    counting.on_done = [&](const StageInfo& info, const StageRun& run) {
      ++runs;
      hits += run.cache_hit ? 1 : 0;
      if (observer.on_done) observer.on_done(info, run);
    };
    RunStages(task, counting, &stage);
    result.fully_cached = runs > 0 && hits == runs;
    if (settings_.last_stage == kMergeStage.name) {
      stage = kMergeStage.name;
      std::string key;
      const auto graph = ReadHeadArtifact<proto::AreaGraph>(store, name, kMergeStage, &key);
      result.areas = graph.areas_size();
      result.passages = graph.passages_size();
      result.components = graph.components();
      result.dropped_parts = graph.dropped_parts();
      result.graph_changed = old_graph != key;
      if (result.graph_changed && publish_) {
        stage = "publish";
        publish_(name, key, graph);
        result.published = true;
      }
    }
    result.ok = true;
    if (failed_maps_.erase(name) > 0) store.ClearFailure(name);
  } catch (const std::exception& error) {
    result.failed_stage = stage;
    result.error = error.what();
    RecordFailure(task, result);
  }
  return result;
}

void MapWorker::RecordFailure(const MapTask& task, MapResult& result) {
  if (!store_) return;  // the store itself failed: the runner reports it
  FailureRecord failure;
  failure.map_name = task.entry.name;
  failure.stage = result.failed_stage;
  failure.message = result.error;
  failure.source_path = task.entry.path;
  try {
    store_->RecordFailure(failure);
    failed_maps_.insert(task.entry.name);
    result.failure_recorded = true;
  } catch (const std::exception&) {
    // The failure is still reported to the runner, which records it later.
  }
}

}  // namespace areagraph

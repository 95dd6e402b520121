#include "runner/run/map_worker.h"

#include <exception>
#include <memory>

#include "stages/import/import_stage.h"
#include "store/write_behind_store.h"

namespace areagraph {

MapWorker::MapWorker(RunSettings settings, GraphPublisher publish)
    : settings_(std::move(settings)), publish_(std::move(publish)) {}

void MapWorker::CloseStore() {
  failures_.reset();
  store_.reset();
}

void MapWorker::FinishWrites() {
  if (!store_) return;
  try {
    store_->FinishWrites();
  } catch (const std::exception&) {
  }
}

MapOutcome MapWorker::Run(const MapTask& task, const PipelineObserver& observer) {
  if (!store_) {
    try {
      store_ = OpenWriteBehindStore(settings_.store_path);
      failures_ = std::make_unique<FailureLog>(*store_);
    } catch (const std::exception& error) {
      store_.reset();  // the runner records the failure once the workers are gone
      MapOutcome outcome;
      outcome.error = error.what();
      return outcome;
    }
  }
  // The file is read once: the digested bytes are the decoded ones.
  auto source = std::make_shared<ImportSource>();
  MapImport import;
  import.read_inputs = [&] {* source = ReadImportSource(task.entry.path);
  return ImportInputs(*source);
};
import.decode = [&] {
  return std::make_unique<proto::GridMap>(ImportGridMap(*source, task.options.import()));
};  // namespace areagraph
return RunOneMap(*store_, *failures_, task.entry.name, task.entry.path, import, task.options,
                 settings_.map, observer, publish_);
}

}  // namespace areagraph

#include "runner/run/collection_run.h"

#include <unistd.h>

#include <algorithm>
#include <iostream>
#include <memory>
#include <optional>
#include <thread>

#include "common/error.h"
#include "common/json.h"
#include "common/process_setup/huge_page_restart.h"
#include "common/process_setup/worker_heap.h"
#include "runner/live/area_graph_publisher.h"
#include "runner/run/fault_injection.h"
#include "runner/run/interruption.h"
#include "runner/run/process_pool.h"
#include "runner/run/run_report.h"
#include "runner/run/shard.h"
#include "runner/run/worker_events.h"
#include "runner/run/worker_threads.h"
#include "stages/common/pipeline_options_check.h"
#include "store/sqlite_store_creation.h"

namespace areagraph {
namespace {

std::vector<MapTask> TasksFrom(const RunFlags& flags, const proto::PipelineOptions& options) {
  std::optional<Shard> shard;
  if (!flags.shard.empty()) shard = ParseShard(flags.shard);
  std::vector<MapTask> tasks;
  std::vector<std::string> notes;
  std::vector<MapEntry> entries = CollectMaps(flags.maps, &notes);
  for (const std::string& note : notes) std::cerr << "ag-run: " << note << "\n";
  for (MapEntry& entry : entries) {
    if (shard && !InShard(entry.name, *shard)) continue;
    proto::PipelineOptions map_options = OptionsForMap(options, entry);
    CheckPipelineOptions(map_options);
    tasks.push_back({std::move(entry), std::move(map_options)});
  }
  return tasks;
}

bool HasBigMap(const std::vector<MapTask>& tasks) {
  return std::any_of(tasks.begin(), tasks.end(),
                     [](const MapTask& task) { return IsBigMapImage(task.entry.path); });
}

GraphPublisher MakePublisher(const std::string& url) {
  if (url.empty()) return nullptr;
  AreaGraphPublisher probe(url);  // a bad URL fails here, before any map runs
  auto publisher = std::make_shared<std::unique_ptr<AreaGraphPublisher>>();
  // Each worker process makes its own LCM instance on first use.
  return [publisher, url](const std::string& name, const std::string& key,
                          const proto::AreaGraph& graph) {
    if (!*publisher) *publisher = std::make_unique<AreaGraphPublisher>(url);
    (*publisher)->Publish(name, key, graph);
  };
}

void RecordLeftoverFailures(ArtifactStore& store, const RunReport& report) {
  for (const FailureRecord& failure : report.UnrecordedFailures()) store.RecordFailure(failure);
}

// Records what no worker could and folds a log that no worker folded (the
// last task crashed, the run was stopped, someone else had the store open).
// Returns what to tell the user when the log could not be folded, or "" when
// the file alone is the store (or another process still uses it and folds it
// when it closes).
std::string FinishStore(const std::string& store_path, const RunReport& report) {
  if (report.UnrecordedFailures().empty() && !HasWriteAheadLog(store_path)) return "";
  const std::unique_ptr<ArtifactStore> store = OpenArtifactStore(store_path);
  RecordLeftoverFailures(*store, report);
  try {
    store->FoldWriteAheadLog();
  } catch (const StoreError& error) {
    store->LeaveWriteAheadLogOnClose();  // said once, here
    return error.what();
  }
  return "";
}

}  // namespace

int RunCollection(const RunFlags& flags) {
  const RunSettings settings = SettingsFrom(flags);
  const proto::PipelineOptions options = LoadPipelineOptions(flags.stage);
  const std::vector<MapTask> tasks = TasksFrom(flags, options);
  // Before the store is touched: the fresh start runs from main again.
  if (MayRestartWithHugePageTunable() && HasBigMap(tasks)) RestartWithHugePageTunable();
  const GraphPublisher publish = MakePublisher(flags.publish ? flags.url : "");
  // Fails early on a store that is unwritable, locked, foreign or too new;
  // closed again because SQLite connections must not cross fork(). Its log
  // stays for the workers: the last of them folds it, syncing the file once.
  // A store made just now has nothing to check (sqlite_store_creation.h):
  // not opening it saves a connection, the log's and index's creation and a
  // schema read per cold run; the first worker's open does that work anyway.
  if (!CreateNewStoreFile(settings.store_path)) {
    OpenArtifactStore(settings.store_path)->LeaveWriteAheadLogOnClose();
  }

  ProgressDisplay progress(static_cast<int>(tasks.size()), isatty(STDERR_FILENO) == 1);
  RunReport report(tasks, progress);
  std::unique_ptr<MapWorker> worker;  // made in each worker process
  // ProcessPool starts no more workers than there are maps.
  const int workers = std::max(1, std::min(flags.jobs, static_cast<int>(tasks.size())));
  const int threads = ThreadsPerMap(flags.threads_per_map,
                                    static_cast<int>(std::thread::hardware_concurrency()), workers);
  ProcessPool pool(
      flags.jobs,
      [&](int task, EventWriter& events) {
        if (!worker) {
          // Before the first map, which decides for the process: a small
          // map's buffers then come from huge pages.
          if (GetsHugePageHeap(tasks[task].entry.path)) PrepareWorkerHeap();
          UseThreadsPerMap(threads);
          worker = std::make_unique<MapWorker>(settings, publish);
        }
        PipelineObserver observer;
        observer.on_start = [&](const StageInfo& stage) {
          events.Write(StageStartedEvent(stage));
          MaybeInjectCrash(tasks[task].entry.name, stage, [&] { worker->FinishWrites(); });
        };
        observer.on_done = [&](const StageInfo& stage, const StageRun& run) {
          events.Write(StageDoneEvent(stage, run));
        };
        events.Write(MapEndedEvent(worker->Run(tasks[task], observer)));
      },
      [&](int task, const std::string& event) { ApplyWorkerEvent(event, task, report); },
      [&](int task, const std::string& crash) {
        if (!crash.empty()) report.MapCrashed(task, crash);
      },
      [&] { progress.Tick(); },
      [&](bool last) {
        // Workers end without closing their stores; the last one closes its
        // own, which folds everyone's log into the file.
        if (last && worker) worker->CloseStore();
      });
  {
    const Interruption interruption;  // SIGINT, SIGTERM: stop, fold, say so
    pool.StopWhen(&Interruption::signal());
    pool.Run(static_cast<int>(tasks.size()));
  }
  progress.Finish();

  proto::RunSummary summary = report.Summary(flags.jobs, flags.shard);
  summary.set_huge_page_restart(RestartedWithHugePageTunable());
  const std::string unfolded = FinishStore(settings.store_path, report);
  if (pool.stopped()) {
    throw Error(std::string("stopped by ") + Interruption::SignalName(Interruption::signal()) +
                " after " + std::to_string(summary.succeeded() + summary.failed()) + " of " +
                std::to_string(tasks.size()) +
                " maps; every map that finished is in the store, and the same command does the "
                "rest" +
                (unfolded.empty() ? "" : "; " + unfolded));
  }
  if (flags.json) {
    std::cout << MessageToJson(summary, /*with_defaults=*/true);
  } else {
    PrintSummary(summary, std::cout);
  }
  if (!unfolded.empty()) throw Error(unfolded);
  return summary.failed() > 0 ? 1 : 0;
}

}  // namespace areagraph

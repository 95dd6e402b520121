// ag-run: the whole pipeline for one map or a collection, through the cache,
// with parallel worker processes, failures recorded, and an optional LCM
// publisher for live consumers.
#include <google/protobuf/util/json_util.h>
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <csignal>
#include <cstdlib>
#include <iostream>
#include <memory>
#include <thread>

#include "runner/live/area_graph_publisher.h"
#include "runner/run/map_collection.h"
#include "runner/run/map_worker.h"
#include "runner/run/process_pool.h"
#include "runner/run/run_report.h"
#include "runner/run/shard.h"
#include "stages/common/command_line.h"
#include "stages/import/import_stage.h"
#include "stages/merge/area_graph_builder.h"
#include "stages/prune/topology_graph_builder.h"
#include "store/error.h"
#include "tools/report/collection_report.h"

namespace areagraph {
namespace {

struct RunFlags {
  StageCommandLine stage;  // --store, --options, --set, --force
  std::vector<std::string> maps;
  std::string from_stage;
  std::string only_stage;
  int jobs = 0;
  std::string shard;
  std::string publish_url;
  bool json = false;
  std::string report_dir;
};

void CheckStageName(const std::string& name, const char* flag) {
  for (const StageInfo& stage : kAllStages) {
    if (name == stage.name) return;
  }
  throw OptionsError(std::string(flag) + " '" + name +
                     "' is not a stage; stages: import, clean, voronoi, prune, cut, merge");
}

RunSettings SettingsFrom(const RunFlags& flags) {
  RunSettings settings;
  settings.store_path = flags.stage.store_path;
  settings.force = flags.stage.force;
  if (!flags.from_stage.empty()) {
    CheckStageName(flags.from_stage, "--from");
    settings.first_stage = flags.from_stage;
  }
  if (!flags.only_stage.empty()) {
    CheckStageName(flags.only_stage, "--only");
    settings.first_stage = settings.last_stage = flags.only_stage;
  }
  return settings;
}

std::vector<MapTask> TasksFrom(const RunFlags& flags, const proto::PipelineOptions& options) {
  std::optional<Shard> shard;
  if (!flags.shard.empty()) shard = ParseShard(flags.shard);
  std::vector<MapTask> tasks;
  for (MapEntry& entry : CollectMaps(flags.maps)) {
    if (shard && !InShard(entry.name, *shard)) continue;
    proto::PipelineOptions map_options = OptionsForMap(options, entry);
    CheckImportOptions(map_options.import());
    CheckPruneOptions(map_options.prune());
    CheckMergeOptions(map_options.merge());
    tasks.push_back({std::move(entry), std::move(map_options)});
  }
  return tasks;
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

// Test hook: AG_RUN_FAULT=crash:<map>:<stage> kills the worker with SIGSEGV
// when that stage of that map starts, standing in for a crash inside CGAL so
// that tests can check the isolation of crashes.
void MaybeInjectCrash(const std::string& map_name, const StageInfo& stage) {
  static const char* fault = std::getenv("AG_RUN_FAULT");
  if (fault != nullptr && std::string(fault) == "crash:" + map_name + ":" + stage.name) {
    std::raise(SIGSEGV);
  }
}

// What a worker writes about one map, and how the runner reads it back.
void WriteResult(EventWriter& events, const MapResult& result) {
  events.Write({"R", result.ok ? "1" : "0", std::to_string(result.areas),
                std::to_string(result.passages), result.fully_cached ? "1" : "0",
                result.published ? "1" : "0", result.failure_recorded ? "1" : "0",
                result.failed_stage, result.error});
}

MapResult ReadResult(const std::vector<std::string>& fields) {
  MapResult result;
  if (fields.size() < 9) return result;
  result.ok = fields[1] == "1";
  result.areas = std::stoi(fields[2]);
  result.passages = std::stoi(fields[3]);
  result.fully_cached = fields[4] == "1";
  result.published = fields[5] == "1";
  result.failure_recorded = fields[6] == "1";
  result.failed_stage = fields[7];
  result.error = fields[8];
  return result;
}

void RecordLeftoverFailures(const std::string& store_path, const RunReport& report) {
  if (report.UnrecordedFailures().empty()) return;
  const std::unique_ptr<ArtifactStore> store = OpenArtifactStore(store_path);
  for (const FailureRecord& failure : report.UnrecordedFailures()) store->RecordFailure(failure);
}

int Run(const RunFlags& flags) {
  const RunSettings settings = SettingsFrom(flags);
  if (flags.jobs < 1 || flags.jobs > 1024) {
    throw OptionsError("--jobs " + std::to_string(flags.jobs) + " must be between 1 and 1024");
  }
  const proto::PipelineOptions options = LoadPipelineOptions(flags.stage);
  const std::vector<MapTask> tasks = TasksFrom(flags, options);
  const GraphPublisher publish = MakePublisher(flags.publish_url);
  // Fails early on a store that is unwritable, locked, foreign or too new;
  // closed again because SQLite connections must not cross fork().
  OpenArtifactStore(settings.store_path).reset();

  ProgressDisplay progress(static_cast<int>(tasks.size()), isatty(STDERR_FILENO) == 1);
  RunReport report(tasks, progress);
  std::unique_ptr<MapWorker> worker;  // made in each worker process
  ProcessPool pool(
      flags.jobs,
      [&](int task, EventWriter& events) {
        if (!worker) worker = std::make_unique<MapWorker>(settings, publish);
        PipelineObserver observer;
        observer.on_start = [&](const StageInfo& stage) {
          events.Write({"S", stage.name});
          MaybeInjectCrash(tasks[task].entry.name, stage);
        };
        observer.on_done = [&](const StageInfo& stage, const StageRun& run) {
          events.Write(
              {"D", stage.name, run.cache_hit ? "1" : "0", std::to_string(run.elapsed_ms)});
        };
        WriteResult(events, worker->Run(tasks[task], observer));
      },
      [&](int task, const std::vector<std::string>& fields) {
        if (fields[0] == "S" && fields.size() >= 2) report.StageStarted(task, fields[1]);
        if (fields[0] == "D" && fields.size() >= 4) {
          report.StageDone(task, fields[1], fields[2] == "1", std::stod(fields[3]));
        }
        if (fields[0] == "R") report.MapEnded(task, ReadResult(fields));
        if (fields[0] == "!" && fields.size() >= 2) report.MapCrashed(task, fields[1]);
      },
      [&](int task, const std::string& crash) {
        if (!crash.empty()) report.MapCrashed(task, crash);
      },
      [&] { progress.Tick(); });
  pool.Run(static_cast<int>(tasks.size()));
  progress.Finish();

  const proto::RunSummary summary = report.Summary(flags.jobs, flags.shard);
  RecordLeftoverFailures(settings.store_path, report);
  if (flags.json) {
    std::string json;
    google::protobuf::util::JsonPrintOptions print;
    print.add_whitespace = true;
    print.always_print_primitive_fields = true;
    print.preserve_proto_field_names = true;
    (void)google::protobuf::util::MessageToJsonString(summary, &json, print);
    std::cout << json;
  } else {
    PrintSummary(summary, std::cout);
  }
  if (!flags.report_dir.empty()) WriteRunReport(settings.store_path, tasks, flags.report_dir);
  return summary.failed() > 0 ? 1 : 0;
}

}  // namespace
}  // namespace areagraph

int main(int argc, char** argv) {
  using namespace areagraph;
  CLI::App app{
      "Runs the whole pipeline (import, clean, voronoi, prune, cut, merge) for maps through "
      "the store's cache: a stage whose cache key is stored does no work. MAP is an image "
      "(with its map_server YAML beside it), a directory searched recursively for images, "
      "or a manifest (.tsv/.csv with columns path, name and option keys such as "
      "cut.room_width_m). A map that fails is recorded in the store (ag-inspect --failures) "
      "and the others go on; the exit status is 1 when any map failed."};
  RunFlags flags;
  flags.jobs = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  app.add_option("--store", flags.stage.store_path, "artifact store (SQLite file)")
      ->capture_default_str();
  app.add_option("--options", flags.stage.options_file, "pipeline options (protobuf text format)");
  app.add_option("--set", flags.stage.overrides, "override one option: stage.field=value");
  CLI::Option* from = app.add_option("--from", flags.from_stage,
                                     "start at this stage; earlier stages' heads are its inputs");
  app.add_option("--only", flags.only_stage, "run this stage only")->excludes(from);
  app.add_flag("--force", flags.stage.force, "recompute even when the cache holds the result");
  app.add_option("--jobs,-j", flags.jobs, "maps processed in parallel (worker processes)")
      ->capture_default_str();
  app.add_option("--shard", flags.shard,
                 "K/N: run only the maps whose name hashes to K modulo N (0 <= K < N)");
  app.add_option("--publish", flags.publish_url,
                 "publish each new or changed Area Graph on LCM channel AREA_GRAPH (URL "
                 "optional; default " +
                     std::string(kDefaultLcmUrl) + ")")
      ->expected(0, 1)
      ->default_str(kDefaultLcmUrl);
  app.add_flag("--json", flags.json, "print the summary as JSON");
  app.add_option("--report", flags.report_dir,
                 "write DIR/index.html (a table of the maps) and a viewer page per map");
  app.add_option("MAP", flags.maps, "map image, directory or manifest")->required();
  return RunCommand("ag-run", app, argc, argv, [&] {
    if (app.get_option("--publish")->count() > 0 && flags.publish_url.empty()) {
      flags.publish_url = kDefaultLcmUrl;
    }
    return Run(flags);
  });
}

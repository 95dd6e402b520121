#include "runner/run/run_report.h"

#include <cstdio>
#include <iomanip>

#include "stages/pipeline/stage_table.h"

namespace areagraph {

RunReport::RunReport(const std::vector<MapTask>& tasks, ProgressDisplay& progress)
    : tasks_(tasks),
      progress_(progress),
      start_(std::chrono::steady_clock::now()),
      last_stage_(tasks.size()),
      compute_ms_(tasks.size(), 0),
      ended_(tasks.size(), false) {
  summary_.set_maps(static_cast<int64_t>(tasks.size()));
}

void RunReport::StageStarted(int task, const std::string& stage) { last_stage_[task] = stage; }

void RunReport::StageDone(int task, const std::string& stage, bool hit, double elapsed_ms) {
  StageCounts& counts = stages_[stage];
  (hit ? counts.hits : counts.misses) += 1;
  counts.compute_ms += elapsed_ms;
  compute_ms_[task] += elapsed_ms;
}

void RunReport::MapEnded(int task, const MapOutcome& result) {
  if (ended_[task]) return;
  ended_[task] = true;
  const std::string& name = tasks_[task].entry.name;
  if (!result.ok) {
    Fail(task, result.failed_step, result.error, result.failure_recorded);
    return;
  }
  summary_.set_succeeded(summary_.succeeded() + 1);
  summary_.set_areas(summary_.areas() + result.areas);
  summary_.set_passages(summary_.passages() + result.passages);
  summary_.set_components(summary_.components() + result.components);
  summary_.set_dropped_parts(summary_.dropped_parts() + result.dropped_parts);
  if (result.fully_cached) summary_.set_fully_cached(summary_.fully_cached() + 1);
  if (result.published) summary_.set_published(summary_.published() + 1);
  std::string line =
      std::to_string(result.areas) + " areas, " + std::to_string(result.passages) + " passages";
  if (result.components > 1) line += ", " + std::to_string(result.components) + " components";
  if (result.dropped_parts > 0) {
    line += ", " + std::to_string(result.dropped_parts) + " small parts dropped";
  }
  char how[64];
  if (result.fully_cached) {
    std::snprintf(how, sizeof(how), " (all cached)");
  } else {
    std::snprintf(how, sizeof(how), " (computed in %.2f s)", compute_ms_[task] / 1000);
  }
  progress_.MapDone(false, name + ": " + line + how);
}

void RunReport::MapCrashed(int task, const std::string& what) {
  if (ended_[task]) return;  // the worker died after reporting the map
  ended_[task] = true;
  Fail(task, last_stage_[task], what, /*recorded=*/false);
}

void RunReport::Fail(int task, const std::string& stage, const std::string& message,
                     bool recorded) {
  const MapTask& map = tasks_[task];
  summary_.set_failed(summary_.failed() + 1);
  proto::RunSummary::MapFailure* failure = summary_.add_failures();
  failure->set_map(map.entry.name);
  failure->set_stage(stage);
  failure->set_message(message);
  failure->set_path(map.entry.path);
  if (!recorded) unrecorded_.push_back({map.entry.name, stage, message, map.entry.path, ""});
  progress_.MapDone(
      true, map.entry.name + ": FAILED" + (stage.empty() ? "" : " in " + stage) + ": " + message);
}

proto::RunSummary RunReport::Summary(int jobs, const std::string& shard) const {
  proto::RunSummary summary = summary_;
  const double wall_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  summary.set_wall_s(wall_s);
  const int64_t ended = summary.succeeded() + summary.failed();
  summary.set_maps_per_s(wall_s > 0 ? ended / wall_s : 0);
  summary.set_jobs(jobs);
  summary.set_shard(shard);
  int64_t hits = 0, misses = 0;
  for (const StageDefinition& stage : StageTable()) {
    const auto it = stages_.find(stage.info.name);
    if (it == stages_.end()) continue;
    proto::RunSummary::StageSummary* out = summary.add_stages();
    out->set_stage(stage.info.name);
    out->set_hits(it->second.hits);
    out->set_misses(it->second.misses);
    out->set_compute_s(it->second.compute_ms / 1000);
    hits += it->second.hits;
    misses += it->second.misses;
  }
  summary.set_cache_hits(hits);
  summary.set_cache_misses(misses);
  return summary;
}

void PrintSummary(const proto::RunSummary& summary, std::ostream& out) {
  out << "ag-run: " << summary.maps() << " maps: " << summary.succeeded() << " done ("
      << summary.fully_cached() << " fully cached), " << summary.failed() << " failed, in "
      << std::fixed << std::setprecision(1) << summary.wall_s() << " s (" << std::setprecision(2)
      << summary.maps_per_s() << " maps/s, " << summary.jobs()
      << (summary.jobs() == 1 ? " job" : " jobs")
      << (summary.shard().empty() ? "" : ", shard " + summary.shard()) << ")\n";
  out << "  " << summary.areas() << " areas, " << summary.passages() << " passages, "
      << summary.components() << " components, " << summary.dropped_parts()
      << " small parts dropped (prune.min_component_m2)";
  if (summary.published() > 0) out << ", " << summary.published() << " graphs published";
  out << "\n  cache: " << summary.cache_hits() << " hits, " << summary.cache_misses() << " misses";
  if (summary.cache_misses() == 0 && summary.cache_hits() > 0) out << " (every stage was a hit)";
  out << "\n  stage      hits  misses  compute s\n";
  for (const auto& stage : summary.stages()) {
    out << "  " << std::left << std::setw(8) << stage.stage() << std::right << std::setw(7)
        << stage.hits() << std::setw(8) << stage.misses() << std::setw(11) << std::setprecision(2)
        << stage.compute_s() << "\n";
  }
  if (summary.huge_page_restart()) {
    out << "  restarted with glibc.malloc.hugetlb=1 (a map over 5 Mpx)\n";
  }
  for (const auto& failure : summary.failures()) {
    out << "  FAILED " << failure.map()
        << (failure.stage().empty() ? "" : " (" + failure.stage() + ")") << ": "
        << failure.message() << "\n";
  }
}

}  // namespace areagraph

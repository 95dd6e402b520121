#pragma once

#include <chrono>
#include <map>
#include <ostream>
#include <string>
#include <vector>

#include "proto/run_summary.pb.h"
#include "runner/run/map_worker.h"
#include "runner/run/progress_display.h"

namespace areagraph {

// Collects what the workers report about each map into the run's summary,
// and keeps the progress display current. Lives in the runner process.
class RunReport {
 public:
  RunReport(const std::vector<MapTask>& tasks, ProgressDisplay& progress);

  void StageStarted(int task, const std::string& stage);
  void StageDone(int task, const std::string& stage, bool hit, double elapsed_ms);
  void MapEnded(int task, const MapOutcome& result);
  // The worker died while on `task`: a failure in the last stage it started.
  void MapCrashed(int task, const std::string& what);

  // Failures that no worker could write into the store (crashes, an
  // unopenable store), for the runner to record after the workers are gone.
  const std::vector<FailureRecord>& UnrecordedFailures() const { return unrecorded_; }

  proto::RunSummary Summary(int jobs, const std::string& shard) const;

 private:
  struct StageCounts {
    int64_t hits = 0;
    int64_t misses = 0;
    double compute_ms = 0;
  };
  void Fail(int task, const std::string& stage, const std::string& message, bool recorded);

  const std::vector<MapTask>& tasks_;
  ProgressDisplay& progress_;
  std::chrono::steady_clock::time_point start_;
  std::vector<std::string> last_stage_;  // per task; empty before its first stage
  std::vector<double> compute_ms_;       // per task
  std::vector<bool> ended_;              // per task: counted once only
  std::map<std::string, StageCounts> stages_;
  proto::RunSummary summary_;
  std::vector<FailureRecord> unrecorded_;
};

// The summary as the few lines ag-run prints at the end.
void PrintSummary(const proto::RunSummary& summary, std::ostream& out);

}  // namespace areagraph

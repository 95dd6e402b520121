#pragma once

#include <string>

#include "runner/common/map_run.h"
#include "runner/run/run_report.h"
#include "stages/common/stage_info.h"

namespace areagraph {

// The events an ag-run worker sends about its map, serialized (WorkerEvent).
std::string StageStartedEvent(const StageInfo& stage);
std::string StageDoneEvent(const StageInfo& stage, const StageRun& run);
std::string MapEndedEvent(const MapOutcome& outcome);

// Hands one received event about `task` to `report`. A message that does not
// parse is ignored: a worker that dies mid-write is reported by the pool.
void ApplyWorkerEvent(const std::string& event, int task, RunReport& report);

}  // namespace areagraph

#pragma once

#include <string>

#include "runner/run/run_command_line.h"

namespace areagraph {

// ag-run --report DIR, after the run: the report (collection_report.h) of the
// maps that the run's MAP arguments and --shard name, from its store, with
// progress and the index's path on stderr ("ag-run: report: ..."). Without
// MAP arguments: of every map the store holds or records as failed.
void WriteRunReport(const RunFlags& flags, const std::string& dir);

}  // namespace areagraph

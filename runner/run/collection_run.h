#pragma once

#include "runner/run/run_command_line.h"

namespace areagraph {

// ag-run's work: the maps of the collection (options checked for every map
// before the store is touched), run in worker processes, with progress and
// the summary printed at the end. Returns the exit status: 1 when any map
// failed. Throws Error for what stops the whole run. A collection with a
// map over 5 Mpx restarts the program first (huge_page_restart.h).
int RunCollection(const RunFlags& flags);

}  // namespace areagraph

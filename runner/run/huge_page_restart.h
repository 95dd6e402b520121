#pragma once

#include <string>
#include <vector>

#include "runner/run/map_worker.h"

namespace areagraph {

// ag-run on a big map (over kWorkerHugePageMaxPixels, worker_heap.h) starts
// itself again, once, with glibc's tunable glibc.malloc.hugetlb=1 added to
// GLIBC_TUNABLES: then glibc asks for transparent huge pages wherever its heap
// grows and under every mapped buffer. A tunable is read when a process
// starts, so the runner cannot set it for itself or its forked workers any
// other way. Why: on this project's virtual machines a 4-kB page costs 10-40
// us to fault in, and lab_a tiled 8 x 8 faulted in 527 000 of them; with the
// tunable 53 000, 11.8 -> 8.7 s (docs/performance.md, eighteenth pass). Small
// maps gain nothing from it (their workers have PrepareWorkerHeap's reserve)
// and would only pay the second start (about 9 ms), so they do not restart.

// True when `tunables` (GLIBC_TUNABLES, null when unset) already says
// anything about glibc.malloc.hugetlb: the user's value, or this restart's.
bool HasHugePageTunable(const char* tunables);

// GLIBC_TUNABLES with glibc.malloc.hugetlb=1 appended to `tunables`.
std::string WithHugePageTunable(const char* tunables);

// True when some map of `tasks` is a PNG of more than
// kWorkerHugePageMaxPixels pixels (read from its header).
bool HasBigMap(const std::vector<MapTask>& tasks);

// Replaces this process by a fresh start of the same executable with the
// same arguments and the tunable added. Returns only when that could not be
// done (no /proc/self/exe, exec refused): the run then goes on as it is.
void RestartWithHugePageTunable(char** argv);

}  // namespace areagraph

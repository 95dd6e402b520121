#pragma once

#include <cstdint>
#include <string>

namespace areagraph {

// A program that holds a big map (ag-run, ag-pipeline, a stage executable)
// starts itself again, once, with glibc's tunable glibc.malloc.hugetlb=1 added
// to GLIBC_TUNABLES: then glibc asks for transparent huge pages wherever its
// heap grows and under every mapped buffer. A tunable is read when a process
// starts, so a program cannot set it for itself or its forked workers any
// other way. Why: on this project's virtual machines a 4-kB page costs 10-40
// us to fault in, and lab_a tiled 8 x 8 faulted in 512 000 of them; with the
// tunable 50 000, a quarter less time (docs/performance.md, eighteenth pass).
// Small maps gain nothing from it (ag-run's workers have PrepareWorkerHeap's
// reserve) and would only pay the second start (about 9 ms).

// Maps of more pixels than this restart; the same limit above which ag-run's
// workers get no heap reserve (kWorkerHugePageMaxPixels).
inline constexpr int64_t kHugePageRestartPixels = 5'000'000;

// True when `tunables` (GLIBC_TUNABLES, null when unset) already says
// anything about glibc.malloc.hugetlb: the user's value, or this restart's.
bool HasHugePageTunable(const char* tunables);

// GLIBC_TUNABLES with glibc.malloc.hugetlb=1 appended to `tunables`.
std::string WithHugePageTunable(const char* tunables);

// True when the process was not started with the tunable yet (see
// HasHugePageTunable) and so may restart.
bool MayRestartWithHugePageTunable();

// Replaces this process by a fresh start of the same executable with the
// same arguments and the tunable added. Returns only when that could not be
// done (no /proc/self/exe, exec refused): the program then goes on as it is.
// Whatever the process holds open (a store) must be closed first.
void RestartWithHugePageTunable(char** argv);

}  // namespace areagraph

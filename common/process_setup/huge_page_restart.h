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
// tunable 50 000, a quarter less time (docs/performance.md, "Memory between stages").
// Small maps gain nothing from it (ag-run's workers have PrepareWorkerHeap's
// reserve) and would only pay the second start (about 9 ms).

// Maps of more pixels than this restart; the same limit above which ag-run's
// workers get no heap reserve (kWorkerHugePageMaxPixels).
inline constexpr int64_t kHugePageRestartPixels = 5'000'000;

// True when `path` is a PNG of more than kHugePageRestartPixels (read from
// its header): a map for which a program restarts.
bool IsBigMapImage(const std::string& path);

// True when `tunables` (GLIBC_TUNABLES, null when unset) already says
// anything about glibc.malloc.hugetlb: the user's value, or this restart's.
bool HasHugePageTunable(const char* tunables);

// GLIBC_TUNABLES with glibc.malloc.hugetlb=1 appended to `tunables`.
std::string WithHugePageTunable(const char* tunables);

// The restart also sets this variable to the executable's file name
// ("ag-run", "ag-clean", ...), so that the fresh start can tell that it is
// one and say so (HugePageRestartLine): exec keeps the process id, and tests
// and users have no other way to see that a restart happened. Children
// inherit it; only the program it names takes it as its own restart.
inline constexpr char kHugePageRestartVariable[] = "AG_HUGE_PAGE_RESTART";

// True when the process was not started with the tunable yet (see
// HasHugePageTunable), nor by a restart of its own, and so may restart.
bool MayRestartWithHugePageTunable();

// True when this process is the fresh start of its own restart.
bool RestartedWithHugePageTunable();

// "TOOL: restarted with glibc.malloc.hugetlb=1\n" in the process that
// RestartedWithHugePageTunable, "" in any other: the line that programs add
// to their report.
std::string HugePageRestartLine(const std::string& tool);

// The command line that a restart runs again. RunCommand sets it for every
// program, so that no program passes its argv down to where it restarts.
void SetRestartCommandLine(char** argv);

// Replaces this process by a fresh start of the same executable with the
// command line SetRestartCommandLine gave, the tunable and
// kHugePageRestartVariable added. Returns only when that could not be done
// (no command line given, no /proc/self/exe, exec refused): the program then
// goes on as it is, with the environment it was given. Whatever the process
// holds open (a store) must be closed first.
void RestartWithHugePageTunable();

}  // namespace areagraph

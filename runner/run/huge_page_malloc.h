#pragma once

#include <functional>
#include <optional>
#include <string>

namespace areagraph {

// glibc's tunable for malloc to advise its heap growth and its mapped buffers
// of 2 MB or more for transparent huge pages (madvise(MADV_HUGEPAGE), which
// Debian's kernels honour in their "madvise" mode). glibc reads it only when
// a process starts.
inline constexpr char kHugePageMallocTunable[] = "glibc.malloc.hugetlb=1";
// Set in the process that ag-run started again with the tunable (and so in
// its workers): a process that has it never starts again.
inline constexpr char kHugePageMallocMarker[] = "AREAGRAPH_HUGE_PAGE_MALLOC";

// The GLIBC_TUNABLES to start again with, or nothing: when the process has
// neither the marker (it was started again already) nor GLIBC_TUNABLES of
// its own (the user's settings are left as they are), and `wanted` says so
// (asked last: it may read files).
std::optional<std::string> HugePageMallocTunables(const char* user_tunables, const char* marker,
                                                  const std::function<bool()>& wanted);

// Starts this program again (/proc/self/exe with `argv`) with GLIBC_TUNABLES
// set to kHugePageMallocTunable and the marker set, when
// HugePageMallocTunables says so for this process's environment. Returns only
// when it does not start again, or when exec fails (the environment is then
// as it was). Call it before threads start and before anything is written.
//
// Why: ag-run on a large map faulted in its buffers 4 kB at a time (lab_a
// tiled 8 x 8: over 800 000 faults at 20-50 microseconds each on this
// project's virtual machines); glibc's own huge-page mode cut that to tens of
// thousands (docs/performance.md, eleventh pass).
void StartAgainWithHugePageMalloc(char* const* argv, const std::function<bool()>& wanted);

}  // namespace areagraph

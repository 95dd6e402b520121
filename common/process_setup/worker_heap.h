#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>

#include "common/process_setup/huge_page_restart.h"

namespace areagraph {

// What PrepareWorkerHeap did.
struct WorkerHeap {
  bool malloc_settings = false;  // glibc's thresholds were set
  bool huge_pages = false;       // the reserve was advised for huge pages
  size_t reserve_bytes = 0;      // heap set aside above the break it found
};

// glibc's largest automatic mmap threshold on 64-bit (and twice it, the
// largest automatic trim threshold): what a long run's heap settles on anyway.
inline constexpr size_t kWorkerMmapThreshold = size_t{32} << 20;
inline constexpr size_t kWorkerTrimThreshold = size_t{64} << 20;

// The part of the heap that ag-run's workers back with huge pages: most maps of
// areagraph/ stay within it, lab_b and bormann's office_g go beyond (ordinary
// pages from there). Kept under the 64 MB of free heap above which
// ReturnFreedMemory gives memory back, so that a small map's stages never do.
inline constexpr size_t kWorkerHugePageReserve = size_t{48} << 20;

// The largest map (pixels of its PNG) whose worker gets the huge-page heap.
// Chosen on lab_a tiled N x N and bormann's two largest maps
// (docs/performance.md, "Memory between stages"): lab_a 3 x 3 (3.3 Mpx), office_i (3.4)
// and office_g (4.7) took less CPU with it, fewer faults at the same user
// time; from lab_a 4 x 4 (5.9 Mpx) on the worker took more user time than it
// saved in faults (8 x 8: 8-11 s more of 35 s), as it did for ag-render's
// heap too, for a reason not found. Every map of areagraph/, bormann/
// and RobotMap is smaller.
// Larger maps make ag-run start itself again with glibc's huge-page tunable
// (common/process_setup/huge_page_restart.h) instead.
inline constexpr int64_t kWorkerHugePageMaxPixels = kHugePageRestartPixels;

// True when `map_path` is a PNG of at most kWorkerHugePageMaxPixels pixels
// (read from its header). Anything else, a YAML or an unreadable file
// included, is false: its worker keeps glibc's heap as it is.
bool GetsHugePageHeap(const std::string& map_path);

// Makes a worker process's heap cheap to fault in, before its first map: on
// this project's virtual machines every 4-kB page a process touches for the
// first time costs 20-50 microseconds (a 2-MB huge page, the same as a few
// 4-kB ones), and a cold ag-run on a small map spent a quarter of its CPU
// time on 2 000-13 000 such faults (docs/performance.md, "Memory between stages").
//
// - Buffers of up to kWorkerMmapThreshold come from the heap from the start
//   (glibc maps each one over 128 kB afresh until a free raises its
//   threshold), and free memory at the top stays up to kWorkerTrimThreshold.
// - The heap grows once by `reserve_bytes` (only address space: pages are
//   faulted in when used), and that stretch, from its first 2-MB boundary on,
//   is advised for transparent huge pages (madvise(MADV_HUGEPAGE); Debian's
//   kernels ship them in "madvise" mode). The stretch below the boundary is
//   held by one allocation that is never used or freed, so that the heap's
//   next allocations start on a huge page.
// Growth beyond the reserve, and the heap after ReturnFreedMemory gives it
// back, get ordinary pages, as without this call. Nothing that the process
// computes changes; its resident memory may be up to one huge page per
// 2-MB stretch of the reserve it touches larger.
//
// Call it once per process, before threads start. Does nothing but return
// an empty WorkerHeap where there is no glibc heap.
WorkerHeap PrepareWorkerHeap(size_t reserve_bytes = kWorkerHugePageReserve);

}  // namespace areagraph

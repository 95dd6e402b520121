#pragma once

#include <cstddef>

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

// The part of the heap that ag-run's workers back with huge pages: every map of
// areagraph/ and bormann/ stays within it (lab_b's worker peaks at about
// 60 MB of heap). Kept under the 64 MB of free heap above which
// ReturnFreedMemory gives memory back, so that a small map's stages never do.
inline constexpr size_t kWorkerHugePageReserve = size_t{48} << 20;

// Makes a worker process's heap cheap to fault in, before its first map: on
// this project's virtual machines every 4-kB page a process touches for the
// first time costs 20-50 microseconds (a 2-MB huge page, the same as a few
// 4-kB ones), and a cold ag-run on a small map spent a quarter of its CPU
// time on 2 000-13 000 such faults (docs/performance.md, 2026-12-02).
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

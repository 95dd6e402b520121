#pragma once

#include <cstddef>
#include <cstdint>

namespace areagraph {

// Makes the heap of a short-lived process cheap to fault in: buffers of up to
// 32 MB come from the heap instead of fresh mappings of their own, freed
// memory stays for the next allocation instead of going back to the system,
// and the first `reserve_bytes` of heap growth ask the kernel for huge pages
// (madvise(MADV_HUGEPAGE); transparent huge pages in "madvise" mode, as
// Debian ships them). Why: on this project's virtual machines a page fault
// costs 15-40 microseconds, and ag-render of a Voronoi diagram spent half of
// its CPU time faulting in 11 000 pages of buffers it writes once. Nothing
// changes in what the process computes; its resident memory may be up to one
// huge page (2 MB) per touched 2-MB stretch of the reserve larger.
//
// Call it first thing in main, before threads start. Returns whether the
// huge-page advice was taken (false where there is no glibc heap or the
// kernel refuses: then only the malloc settings apply, or nothing).
bool UseFaultThriftyHeap(size_t reserve_bytes);

// For a process about to hold far more than its reserve (a big map's canvas,
// masks and edge lists): from now on every buffer comes from the heap, also
// those over 32 MB, which glibc would otherwise map on their own in 4-kB
// pages, and the heap grows once more by `more_bytes` (at most 1 GB), advised
// for huge pages like the reserve. Freed memory stays in the process. Returns
// whether the advice was taken.
bool GrowFaultThriftyHeap(size_t more_bytes);

// Takes the free top of glibc's heap below `boundary` with one allocation
// that is never touched nor freed, so that the heap's next allocations start
// at `boundary` (a huge-page boundary of an advised stretch). Returns false,
// holding nothing, when the top does not reach that far or malloc took the
// allocation from elsewhere.
bool HoldHeapBelow(uintptr_t boundary);

}  // namespace areagraph

#include "common/process_setup/page_fault_thrift.h"

#include <cstdint>
#include <cstdlib>  // defines __GLIBC__ where it applies

#if defined(__GLIBC__)
#include <malloc.h>
#include <sys/mman.h>
#include <unistd.h>
#endif

namespace areagraph {

#if defined(__GLIBC__) && defined(MADV_HUGEPAGE)
bool HoldHeapBelow(uintptr_t boundary) {
  // glibc's chunk layout on 64-bit: a size word before each allocation,
  // 16-byte alignment, 16 bytes from a chunk's start to its memory.
  constexpr size_t kSizeWord = sizeof(size_t);
  constexpr uintptr_t kChunkAlign = 2 * kSizeWord, kChunkToMemory = 2 * kSizeWord;
  const size_t top_bytes = mallinfo2().keepcost;  // the top chunk, up to the break
  const uintptr_t top_start = reinterpret_cast<uintptr_t>(sbrk(0)) - top_bytes;
  if (top_start % kChunkAlign != 0 || boundary < top_start + 64 * kChunkAlign) return false;
  const size_t request = (boundary - top_start) - kSizeWord;  // its chunk ends at `boundary`
  void* filler = malloc(request);
  if (filler == nullptr) return false;
  if (reinterpret_cast<uintptr_t>(filler) - kChunkToMemory != top_start ||
      mallinfo2().keepcost != top_bytes - (boundary - top_start)) {
    free(filler);  // it came from somewhere else: nothing to hold
    return false;
  }
  return true;  // held for the life of the process, never touched beyond its first page
}

namespace {

// glibc's largest threshold on 64-bit: bigger buffers are mapped on their own
// (and given back when freed) unless mappings are turned off.
constexpr size_t kMmapThreshold = size_t{32} << 20;
constexpr size_t kMaxReserve = size_t{1} << 30;

// Grows the heap once by `reserve_bytes` above its free top (M_TOP_PAD is
// what malloc adds to its next growth of the break; the probe must not fit in
// the free top), then advises that stretch for huge pages; growth beyond it
// gets ordinary pages.
bool ReserveHugePageHeap(size_t reserve_bytes) {
  constexpr uintptr_t kHugePage = uintptr_t{2} << 20;
  const size_t probe_bytes = mallinfo2().keepcost + (size_t{64} << 10);
  mallopt(M_TOP_PAD, static_cast<int>(reserve_bytes));
  // Volatile, or the compiler drops the pair of calls.
  void* volatile probe = malloc(probe_bytes);
  // Splitting the probe off the top wrote the top's header just after it:
  // that page is faulted in already, its huge page is lost.
  const uintptr_t touched = reinterpret_cast<uintptr_t>(probe) + probe_bytes + 64;
  free(probe);
  mallopt(M_TOP_PAD, 128 << 10);  // glibc's default again
  if (probe == nullptr) return false;
  const auto end = reinterpret_cast<uintptr_t>(sbrk(0));
  const uintptr_t first = (touched + kHugePage - 1) & ~(kHugePage - 1),
                  last = end & ~(kHugePage - 1);
  if (last <= first) return false;
  // Advised first: taking the stretch below writes the top's header at
  // `first`, and a page faulted in before the advice keeps ordinary pages.
  if (madvise(reinterpret_cast<void*>(first), last - first, MADV_HUGEPAGE) != 0) return false;
  // A small picture's buffers would all fit below the first boundary, in
  // ordinary pages: lab_a's import picture 450 faults, 200 with this.
  HoldHeapBelow(first);
  return true;
}

}  // namespace

bool UseFaultThriftyHeap(size_t reserve_bytes) {
  mallopt(M_MMAP_THRESHOLD, static_cast<int>(kMmapThreshold));
  mallopt(M_TRIM_THRESHOLD, 1 << 30);
  // A probe of the threshold or more would be mapped, not grow the heap.
  if (reserve_bytes == 0 || reserve_bytes > kMaxReserve ||
      mallinfo2().keepcost + (size_t{64} << 10) >= kMmapThreshold) {
    return false;
  }
  return ReserveHugePageHeap(reserve_bytes);
}

bool GrowFaultThriftyHeap(size_t more_bytes) {
  mallopt(M_MMAP_MAX, 0);
  if (more_bytes == 0 || more_bytes > kMaxReserve) return false;
  return ReserveHugePageHeap(more_bytes);
}

#else
bool HoldHeapBelow(uintptr_t) { return false; }
bool UseFaultThriftyHeap(size_t) { return false; }
bool GrowFaultThriftyHeap(size_t) { return false; }
#endif

}  // namespace areagraph

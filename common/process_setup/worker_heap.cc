#include "common/process_setup/worker_heap.h"

#include <algorithm>
#include <cstdint>
#include <cstdlib>  // defines __GLIBC__ where it applies

#if defined(__GLIBC__)
#include <malloc.h>
#include <sys/mman.h>
#include <unistd.h>
#endif

#include "common/png_header.h"
#include "common/process_setup/page_fault_thrift.h"

namespace areagraph {

bool GetsHugePageHeap(const std::string& map_path) {
  const std::optional<int64_t> pixels = PngFilePixels(map_path);
  return pixels && *pixels <= kWorkerHugePageMaxPixels;
}

#if defined(__GLIBC__)
namespace {

constexpr uintptr_t kHugePage = uintptr_t{2} << 20;
// glibc's chunk layout on 64-bit: a size word before each allocation,
// 16-byte alignment, 16 bytes from a chunk's start to its memory.
constexpr size_t kSizeWord = sizeof(size_t);
constexpr uintptr_t kChunkAlign = 2 * kSizeWord;
constexpr uintptr_t kChunkToMemory = 2 * kSizeWord;
constexpr size_t kDefaultTopPad = size_t{128} << 10;  // glibc's M_TOP_PAD

uintptr_t Break() { return reinterpret_cast<uintptr_t>(sbrk(0)); }

// The chunk that a request of `bytes` takes: one size word more, rounded up.
size_t ChunkBytes(size_t bytes) {
  return (bytes + kSizeWord + kChunkAlign - 1) & ~(kChunkAlign - 1);
}

}  // namespace
#endif

WorkerHeap PrepareWorkerHeap(size_t reserve_bytes) {
  WorkerHeap heap;
#if defined(__GLIBC__) && defined(MADV_HUGEPAGE)
  // Setting any threshold turns glibc's automatic ones off, so both are set.
  heap.malloc_settings = mallopt(M_MMAP_THRESHOLD, static_cast<int>(kWorkerMmapThreshold)) == 1 &&
                         mallopt(M_TRIM_THRESHOLD, static_cast<int>(kWorkerTrimThreshold)) == 1;
  // A larger free top would go back to the system at the first free().
  if (!heap.malloc_settings || reserve_bytes == 0 || reserve_bytes > kWorkerTrimThreshold) {
    return heap;
  }
  // Grow the heap once by the reserve: M_TOP_PAD is what malloc adds to its
  // next growth of the break, and the probe must not fit in the free top.
  const uintptr_t break_before = Break();
  const size_t probe_bytes = mallinfo2().keepcost + (size_t{64} << 10);
  if (probe_bytes >= kWorkerMmapThreshold) return heap;
  mallopt(M_TOP_PAD, static_cast<int>(reserve_bytes));
  void* volatile probe = malloc(probe_bytes);  // volatile: the pair must stay
  if (probe == nullptr) {
    mallopt(M_TOP_PAD, static_cast<int>(kDefaultTopPad));
    return heap;
  }
  // Splitting the probe off the top wrote the top's header just after it:
  // that page is faulted in already and must not be advised.
  const uintptr_t touched_end = reinterpret_cast<uintptr_t>(probe) - kChunkToMemory +
                                ChunkBytes(probe_bytes) + kChunkToMemory;
  free(probe);
  mallopt(M_TOP_PAD, static_cast<int>(kDefaultTopPad));
  const uintptr_t break_after = Break();
  if (break_after <= break_before) return heap;  // no brk heap, or it could not grow
  heap.reserve_bytes = break_after - break_before;

  uintptr_t top_start = break_after - mallinfo2().keepcost;
  // keepcost is the top of the last arena counted: with more than one (not
  // in a worker, which starts single-threaded) use only what surely grew.
  if (top_start > break_before || break_before - top_start > kWorkerTrimThreshold) {
    top_start = break_before;
  }
  const uintptr_t first = (std::max(top_start, touched_end) + kHugePage - 1) & ~(kHugePage - 1);
  const uintptr_t last = break_after & ~(kHugePage - 1);
  if (last <= first) return heap;
  // Advised first: taking the stretch below writes the top's header at
  // `first`, and a page faulted in before the advice keeps its 2 MB on
  // ordinary pages.
  heap.huge_pages = madvise(reinterpret_cast<void*>(first), last - first, MADV_HUGEPAGE) == 0;
  if (heap.huge_pages) HoldHeapBelow(first);
#else
  (void)reserve_bytes;
#endif
  return heap;
}

}  // namespace areagraph

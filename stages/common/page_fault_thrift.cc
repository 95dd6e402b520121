#include "stages/common/page_fault_thrift.h"

#include <cstdint>
#include <cstdlib>  // defines __GLIBC__ where it applies

#if defined(__GLIBC__)
#include <malloc.h>
#include <sys/mman.h>
#include <unistd.h>
#endif

namespace areagraph {

bool UseFaultThriftyHeap(size_t reserve_bytes) {
#if defined(__GLIBC__) && defined(MADV_HUGEPAGE)
  // glibc's largest threshold on 64-bit: bigger buffers are still mapped on
  // their own (and given back when freed).
  constexpr size_t kMmapThreshold = size_t{32} << 20;
  mallopt(M_MMAP_THRESHOLD, static_cast<int>(kMmapThreshold));
  mallopt(M_TRIM_THRESHOLD, 1 << 30);
  // Grow the heap once by the whole reserve (M_TOP_PAD is what malloc adds to
  // its next growth of the break), then advise that stretch; growth beyond it
  // gets ordinary pages. The probe must not fit in the heap's free top.
  const size_t top = mallinfo2().keepcost;
  const size_t probe_bytes = top + (size_t{64} << 10);
  if (reserve_bytes == 0 || probe_bytes >= kMmapThreshold || reserve_bytes > (size_t{1} << 30)) {
    return false;
  }
  constexpr uintptr_t kHugePage = uintptr_t{2} << 20;
  mallopt(M_TOP_PAD, static_cast<int>(reserve_bytes));
  const auto start = reinterpret_cast<uintptr_t>(sbrk(0));
  // Volatile, or the compiler drops the pair of calls.
  void* volatile probe = malloc(probe_bytes);
  free(probe);
  mallopt(M_TOP_PAD, 128 << 10);  // glibc's default again
  const auto end = reinterpret_cast<uintptr_t>(sbrk(0));
  const uintptr_t first = (start + kHugePage - 1) & ~(kHugePage - 1), last = end & ~(kHugePage - 1);
  if (last <= first) return false;
  return madvise(reinterpret_cast<void*>(first), last - first, MADV_HUGEPAGE) == 0;
#else
  (void)reserve_bytes;
  return false;
#endif
}

}  // namespace areagraph

#include "common/process_setup/freed_memory.h"

#include <cstddef>
#include <cstdlib>  // defines __GLIBC__ where it applies

#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace areagraph {
namespace {

// Below this much free heap, giving pages back is not worth the page fault
// that each page costs when it is used again (a few percent of the CPU time
// of a map of areagraph/, whose whole heap stays under 100 MB).
constexpr size_t kMinFreeBytes = size_t{64} << 20;

}  // namespace

void ReturnFreedMemory() {
#if defined(__GLIBC__)
  // Only when much of the heap is free, however much is in use: a stage that
  // keeps a big artifact (cut's graph while merge runs) would otherwise carry
  // everything freed beside it into the next stage's peak.
  const struct mallinfo2 heap = mallinfo2();
  if (heap.fordblks > kMinFreeBytes) malloc_trim(0);
#endif
}

}  // namespace areagraph

// Shared libraries loaded on first use, for the fast-start executables
// (cmake/FastStart.cmake). OpenCV's static core calls TBB (cv::parallel_for_)
// and LAPACK and BLAS (cv::solve, cv::gemm); loading them at every start was
// 2.5-3 ms of CPU, while ag-render, ag-inspect and many stage runs never call
// them. LCM (with glib) is needed by ag-run only when it publishes.
// cmake/lazy_libraries.sh writes an entry point for each such function
// (the generated assembly); the first call of one lands here, loads its
// library with dlopen, points the entry's slot at the real function and goes
// on to it, so later calls cost one indirect jump.
#include <dlfcn.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>

#include "common/static_program.h"

extern "C" {
// From the generated assembly, in one order: each function's slot (its
// first-call path, then its address), its library and its name.
extern void* ag_lazy_slots[];
extern const uint32_t ag_lazy_symbol_count;
extern const uint8_t ag_lazy_symbol_library[];
extern const char ag_lazy_symbol_names[];  // back to back, each ending in '\0'
extern const uint32_t ag_lazy_library_count;
extern const char ag_lazy_library_names[];

// Loads the library of function `index`, stores the function's address in
// its slot and returns it. Exits naming the library or function when it
// cannot, as the dynamic loader does at start for a missing library.
void* ag_lazy_resolve(uint32_t index);
}

namespace {

// The `index`th of the '\0'-terminated strings packed in `names`.
const char* Nth(const char* names, uint32_t index) {
  while (index-- > 0) {
    while (*names != '\0') ++names;
    ++names;
  }
  return names;
}

}  // namespace

void* ag_lazy_resolve(uint32_t index) {
  if (index >= ag_lazy_symbol_count) std::abort();
  const char* library = Nth(ag_lazy_library_names, ag_lazy_symbol_library[index]);
  const char* name = Nth(ag_lazy_symbol_names, index);
  if (areagraph::LinkedStatically()) {
    std::fprintf(stderr, "cannot load %s (for %s) into a statically linked program\n", library,
                 name);
    std::_Exit(127);
  }
  // RTLD_GLOBAL, as if linked; a library loaded before is only counted again.
  void* handle = dlopen(library, RTLD_NOW | RTLD_GLOBAL);
  void* address = handle != nullptr ? dlsym(handle, name) : nullptr;
  if (address == nullptr) {
    std::fprintf(stderr, "error while loading %s on first use (for %s): %s\n", library, name,
                 dlerror());
    std::_Exit(127);
  }
  __atomic_store_n(&ag_lazy_slots[index], address, __ATOMIC_RELEASE);
  return address;
}

// The first-call path of every entry point (%r11d: the function's index):
// keeps the argument registers (integer, vector and %rax, which counts a
// variadic call's vector arguments) across ag_lazy_resolve, then jumps to
// the function with the caller's stack and arguments as they were. On entry
// %rsp is 8 modulo 16 (the caller's return address); seven pushes and 128
// bytes leave it at 0, as a call requires.
asm(R"(
  .text
  .globl ag_lazy_trampoline
  .type ag_lazy_trampoline, @function
ag_lazy_trampoline:
  push %rdi
  push %rsi
  push %rdx
  push %rcx
  push %r8
  push %r9
  push %rax
  sub $128, %rsp
  movdqu %xmm0, 0(%rsp)
  movdqu %xmm1, 16(%rsp)
  movdqu %xmm2, 32(%rsp)
  movdqu %xmm3, 48(%rsp)
  movdqu %xmm4, 64(%rsp)
  movdqu %xmm5, 80(%rsp)
  movdqu %xmm6, 96(%rsp)
  movdqu %xmm7, 112(%rsp)
  mov %r11d, %edi
  call ag_lazy_resolve@PLT
  mov %rax, %r11
  movdqu 0(%rsp), %xmm0
  movdqu 16(%rsp), %xmm1
  movdqu 32(%rsp), %xmm2
  movdqu 48(%rsp), %xmm3
  movdqu 64(%rsp), %xmm4
  movdqu 80(%rsp), %xmm5
  movdqu 96(%rsp), %xmm6
  movdqu 112(%rsp), %xmm7
  add $128, %rsp
  pop %rax
  pop %r9
  pop %r8
  pop %rcx
  pop %rdx
  pop %rsi
  pop %rdi
  jmp *%r11
  .size ag_lazy_trampoline, .-ag_lazy_trampoline
)");

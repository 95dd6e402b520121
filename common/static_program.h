#pragma once

// The dynamic section; absent (null) in a statically linked program.
extern "C" __attribute__((weak)) const char _DYNAMIC[];

namespace areagraph {

// True in a fully static program (cmake/FastStart.cmake, ag_fully_static):
// it must not dlopen a library, which would bring a second glibc and C++
// runtime beside its own.
inline bool LinkedStatically() { return _DYNAMIC == nullptr; }

}  // namespace areagraph

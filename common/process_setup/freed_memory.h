#pragma once

namespace areagraph {

// Gives the pages of freed heap memory back to the system. glibc keeps what
// a stage freed (millions of small protobuf and CGAL objects) resident, while
// the next stage's big buffers come from fresh mappings, so without this a
// map's peak memory is the sum of its stages' high-water marks instead of
// the largest one. Does nothing where the C library has no malloc_trim.
void ReturnFreedMemory();

}  // namespace areagraph

#pragma once

namespace areagraph {

// How many threads each map's stages may use (OpenCV's pool, on which
// stages/geometry/parallel_ranges.h splits work) in an ag-run of `workers`
// worker processes on `cores` cores: `requested` when above 0
// (--threads-per-map), else an equal share of the cores, at least 1. Each
// worker runs one map at a time, so without this `workers` pools of `cores`
// threads each would fight over the same cores.
int ThreadsPerMap(int requested, int cores, int workers);

// Sets this process's OpenCV pool to `threads`, before its first stage runs.
// With 1, cv::getNumThreads() says 1 (parallel_ranges.h then splits nothing)
// and parallel_for_ runs on the calling thread, starting no TBB thread
// (checked with strace on ag-run); cv::setNumThreads(0) does the same but
// leaves getNumThreads() at the core count, so the ranges would still be cut.
void UseThreadsPerMap(int threads);

}  // namespace areagraph

#include "runner/run/worker_threads.h"

#include <algorithm>
#include <opencv2/core/utility.hpp>

namespace areagraph {

int ThreadsPerMap(int requested, int cores, int workers) {
  if (requested > 0) return requested;
  return std::max(1, cores / std::max(1, workers));
}

void UseThreadsPerMap(int threads) { cv::setNumThreads(std::max(1, threads)); }

}  // namespace areagraph

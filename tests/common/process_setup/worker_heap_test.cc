// PrepareWorkerHeap: buffers that glibc would map one by one come from the
// heap, and the heap's reserve is faulted in by huge pages. Each case runs in
// a forked child, whose heap the test may change, and reports back through
// its exit status.
#include "common/process_setup/worker_heap.h"

#include <gtest/gtest.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>
#include <vector>

#include "tests/support/test_support.h"

namespace areagraph {
namespace {

constexpr int kSkip = 77;

// Runs `body` in a forked child and returns its exit status (-1 if it died).
int InChild(const std::function<int()>& body) {
  const pid_t pid = fork();
  if (pid == 0) _exit(body());
  int status = 0;
  waitpid(pid, &status, 0);
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

long MinorFaults() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return usage.ru_minflt;
}

// Minor faults of writing 16 MB as 64 buffers of 256 kB, each above glibc's
// first mmap threshold (128 kB): 4 096 pages.
long FaultsOfWritingBuffers() {
  constexpr size_t kBuffer = size_t{256} << 10;
  std::vector<char*> buffers;
  const long before = MinorFaults();
  for (int i = 0; i < 64; ++i) {
    buffers.push_back(static_cast<char*>(malloc(kBuffer)));
    std::memset(buffers.back(), i, kBuffer);
  }
  const long faults = MinorFaults() - before;
  for (char* buffer : buffers) free(buffer);
  return faults;
}

bool TransparentHugePagesOff() {
  std::ifstream in("/sys/kernel/mm/transparent_hugepage/enabled");
  std::string modes;
  std::getline(in, modes);
  return !in || modes.find("[never]") != std::string::npos;
}

TEST(WorkerHeapTest, BuffersOfAWorkerComeFromHugePages) {
  if (TransparentHugePagesOff()) GTEST_SKIP() << "transparent huge pages are off";
  // Without the call every page of the buffers is a fault of its own (unless
  // the kernel gives huge pages to everything, when this test says nothing).
  const int control = InChild([] { return FaultsOfWritingBuffers() > 2000 ? 0 : kSkip; });
  if (control == kSkip) GTEST_SKIP() << "this kernel faults in 16 MB without 4 000 faults";
  ASSERT_EQ(control, 0);

  const int status = InChild([] {
    const WorkerHeap heap = PrepareWorkerHeap();
    if (!heap.malloc_settings || heap.reserve_bytes < kWorkerHugePageReserve) return 2;
    if (!heap.huge_pages) return 3;
    // Eight huge pages and whatever glibc's bookkeeping touches; 4 096
    // without the reserve's advice, some 250 more when the heap does not
    // start its allocations on a huge-page boundary.
    const long faults = FaultsOfWritingBuffers();
    return faults < 100 ? 0 : 4;
  });
  EXPECT_EQ(status, 0) << "2: no settings or reserve, 3: no huge-page advice, 4: too many faults";
}

TEST(WorkerHeapTest, FreedBuffersAreReusedWithoutFaults) {
  // The malloc settings alone, without a reserve: a freed 1-MB buffer stays
  // in the heap, so writing the next one costs no faults (glibc's default
  // maps and unmaps the first such buffers each time).
  const int status = InChild([] {
    const WorkerHeap heap = PrepareWorkerHeap(0);
    if (!heap.malloc_settings || heap.reserve_bytes != 0 || heap.huge_pages) return 2;
    constexpr size_t kBuffer = size_t{1} << 20;
    char* first = static_cast<char*>(malloc(kBuffer));
    std::memset(first, 1, kBuffer);
    free(first);
    const long before = MinorFaults();
    char* second = static_cast<char*>(malloc(kBuffer));
    std::memset(second, 2, kBuffer);
    const long faults = MinorFaults() - before;
    free(second);
    return faults < 16 ? 0 : 3;
  });
  EXPECT_EQ(status, 0) << "2: settings or reserve wrong, 3: the second buffer faulted";
}

std::string WriteFile(const std::string& name, const std::string& bytes) {
  const std::string path = (std::filesystem::temp_directory_path() /
                            ("worker_heap_test_" + std::to_string(getpid()) + "_" + name))
                               .string();
  std::ofstream(path, std::ios::binary) << bytes;
  return path;
}

TEST(WorkerHeapTest, OnlySmallPngMapsGetTheHugePageHeap) {
  const std::string small = WriteFile("small.png", testing::PngHeaderBytes(2000, 2500));  // 5.0 Mpx
  const std::string large = WriteFile("large.png", testing::PngHeaderBytes(2000, 2501));
  const std::string yaml = WriteFile("map.yaml", "image: small.png\nresolution: 0.05\n");
  const std::string truncated =
      WriteFile("truncated.png", testing::PngHeaderBytes(10, 10).substr(0, 20));
  EXPECT_TRUE(GetsHugePageHeap(small));
  EXPECT_FALSE(GetsHugePageHeap(large));
  EXPECT_FALSE(GetsHugePageHeap(yaml));
  EXPECT_FALSE(GetsHugePageHeap(truncated));
  EXPECT_FALSE(GetsHugePageHeap(small + ".missing"));
  for (const std::string& path : {small, large, yaml, truncated}) std::filesystem::remove(path);
}

}  // namespace
}  // namespace areagraph

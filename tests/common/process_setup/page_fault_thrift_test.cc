#include "common/process_setup/page_fault_thrift.h"

#include <gtest/gtest.h>
#include <malloc.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>
#include <string>

#include "tests/support/test_support.h"

namespace areagraph {
namespace {

constexpr size_t kMb = size_t{1} << 20;
constexpr int kSkip = 77;

bool TransparentHugePagesOff() {
  std::ifstream mode("/sys/kernel/mm/transparent_hugepage/enabled");
  std::string text;
  std::getline(mode, text);
  return text.empty() || text.find("[never]") != std::string::npos;
}

TEST(PageFaultThriftTest, BuffersOfSeveralMegabytesComeFromTheHeapNotOwnMappings) {
  UseFaultThriftyHeap(0);
  const size_t mapped_before = mallinfo2().hblks;
  // Without the setting glibc maps an 8-MB buffer on its own (and faults it
  // in afresh each time); with it the buffer is heap memory, reused.
  void* volatile buffer = malloc(8 * kMb);
  ASSERT_NE(buffer, nullptr);
  std::memset(buffer, 1, 8 * kMb);
  EXPECT_EQ(mallinfo2().hblks, mapped_before);
  free(buffer);
  void* volatile again = malloc(8 * kMb);
  EXPECT_EQ(mallinfo2().hblks, mapped_before);
  free(again);
}

TEST(PageFaultThriftTest, TheReservedHeapIsAdvisedForHugePages) {
  if (TransparentHugePagesOff()) GTEST_SKIP() << "transparent huge pages are off here";
  ASSERT_TRUE(UseFaultThriftyHeap(64 * kMb));
  void* volatile buffer = malloc(16 * kMb);
  ASSERT_NE(buffer, nullptr);
  std::memset(buffer, 1, 16 * kMb);
  // Its end lies in the heap's growth (its start may be in free heap from
  // before the call, which keeps ordinary pages).
  const std::string flags = testing::VmFlagsOf(static_cast<char*>(buffer) + 15 * kMb);
  EXPECT_NE(flags.find(" hg"), std::string::npos) << flags;
  free(buffer);
}

long MinorFaults() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return usage.ru_minflt;
}

// In a forked child (the call changes the whole heap for good): a 64-MB
// buffer, which glibc would map on its own in 4-kB pages (16 384 faults to
// write it), comes from the grown heap's huge pages.
TEST(PageFaultThriftTest, GrownHeapHoldsBigBuffersInHugePages) {
  if (TransparentHugePagesOff()) GTEST_SKIP() << "transparent huge pages are off here";
  const pid_t child = fork();
  if (child == 0) {
    UseFaultThriftyHeap(16 * kMb);
    if (!GrowFaultThriftyHeap(256 * kMb)) _exit(2);
    const size_t mapped_before = mallinfo2().hblks;
    const long faults_before = MinorFaults();
    char* volatile buffer = static_cast<char*>(malloc(64 * kMb));
    if (buffer == nullptr) _exit(3);
    std::memset(buffer, 1, 64 * kMb);
    if (mallinfo2().hblks != mapped_before) _exit(4);  // a mapping of its own
    if (testing::VmFlagsOf(buffer + 32 * kMb).find(" hg") == std::string::npos) _exit(5);
    // 32 huge pages and whatever the kernel splits; 16 384 in 4-kB pages.
    _exit(MinorFaults() - faults_before < 1000 ? 0 : 6);
  }
  int status = 0;
  waitpid(child, &status, 0);
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 0)
      << "2: not advised, 3: no memory, 4: mapped on its own, 5: no huge-page flag, 6: faults";
}

// A small process's first buffers start on a huge page of the reserve, not in
// the ordinary pages below its first 2-MB boundary (forked: the call changes
// the heap for good).
TEST(PageFaultThriftTest, FirstBuffersAfterTheReserveAreInHugePages) {
  if (TransparentHugePagesOff()) GTEST_SKIP() << "transparent huge pages are off here";
  const pid_t child = fork();
  if (child == 0) {
    // Where the parent's heap has a large free top already (an earlier test
    // reserved), there is nothing to reserve.
    if (mallinfo2().keepcost > 16 * kMb) _exit(kSkip);
    if (!UseFaultThriftyHeap(64 * kMb)) _exit(2);
    constexpr size_t kBuffer = 1536 << 10;
    const long faults_before = MinorFaults();
    char* volatile buffer = static_cast<char*>(malloc(kBuffer));
    if (buffer == nullptr) _exit(3);
    std::memset(buffer, 1, kBuffer);
    if (testing::VmFlagsOf(buffer).find(" hg") == std::string::npos) _exit(4);
    // One huge page and a few dozen others (here 36); 384 in 4-kB pages.
    _exit(MinorFaults() - faults_before < 100 ? 0 : 5);
  }
  int status = 0;
  waitpid(child, &status, 0);
  ASSERT_TRUE(WIFEXITED(status));
  if (WEXITSTATUS(status) == kSkip) GTEST_SKIP() << "this process's heap has a free top already";
  EXPECT_EQ(WEXITSTATUS(status), 0)
      << "2: not advised, 3: no memory, 4: below the advised stretch, 5: faults";
}

}  // namespace
}  // namespace areagraph

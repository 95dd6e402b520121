// ag-test-huge-page-malloc FILE: starts itself again with glibc's huge-page
// malloc as ag-run does (StartAgainWithHugePageMalloc, wanted), appending a
// line to FILE at each start, then prints the GLIBC_TUNABLES it runs with and
// whether malloc advised a buffer that it mapped on its own for huge pages.
#include <malloc.h>

#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>

#include "runner/run/huge_page_malloc.h"

namespace {

// Whether the mapping that holds `address` has the huge-page advice ("hg").
bool Advised(const void* address) {
  const auto at = reinterpret_cast<uintptr_t>(address);
  std::ifstream smaps("/proc/self/smaps");
  std::string line;
  bool inside = false;
  while (std::getline(smaps, line)) {
    uintptr_t from = 0, to = 0;
    char dash = 0;
    std::istringstream range(line);
    if (range >> std::hex >> from >> dash >> to && dash == '-') {
      inside = from <= at && at < to;
    } else if (inside && line.rfind("VmFlags:", 0) == 0) {
      return line.find(" hg") != std::string::npos;
    }
  }
  return false;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) return 2;
  std::ofstream(argv[1], std::ios::app) << "start\n";
  areagraph::StartAgainWithHugePageMalloc(argv, [] { return true; });
  const char* tunables = std::getenv("GLIBC_TUNABLES");
  // Over glibc's first mmap threshold: a mapping of its own.
  constexpr size_t kBytes = size_t{8} << 20;
  char* volatile buffer = static_cast<char*>(malloc(kBytes));
  std::cout << "tunables=" << (tunables == nullptr ? "" : tunables) << "\n"
            << "advised=" << Advised(buffer + kBytes / 2) << "\n";
  free(buffer);
  return 0;
}

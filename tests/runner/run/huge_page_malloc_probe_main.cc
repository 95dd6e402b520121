// huge-page-malloc-probe FILE: starts itself again with glibc's huge-page
// malloc as ag-run does (StartAgainWithHugePageMalloc, wanted), appending a
// line to FILE at each start, then prints the GLIBC_TUNABLES it runs with and
// whether malloc advised a buffer that it mapped on its own for huge pages.
#include <malloc.h>

#include <cstdlib>
#include <fstream>
#include <iostream>
#include <string>

#include "runner/run/huge_page_malloc.h"
#include "tests/support/test_support.h"

int main(int argc, char** argv) {
  if (argc != 2) return 2;
  std::ofstream(argv[1], std::ios::app) << "start\n";
  areagraph::StartAgainWithHugePageMalloc(argv, [] { return true; });
  const char* tunables = std::getenv("GLIBC_TUNABLES");
  // Over glibc's first mmap threshold: a mapping of its own.
  constexpr size_t kBytes = size_t{8} << 20;
  char* volatile buffer = static_cast<char*>(malloc(kBytes));
  std::cout << "tunables=" << (tunables == nullptr ? "" : tunables) << "\n"
            << "advised="
            << (areagraph::testing::VmFlagsOf(buffer + kBytes / 2).find(" hg") != std::string::npos)
            << "\n";
  free(buffer);
  return 0;
}

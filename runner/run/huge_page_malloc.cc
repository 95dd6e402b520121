#include "runner/run/huge_page_malloc.h"

#include <unistd.h>

#include <cstdlib>

namespace areagraph {

std::optional<std::string> HugePageMallocTunables(const char* user_tunables, const char* marker,
                                                  const std::function<bool()>& wanted) {
  if (marker != nullptr || user_tunables != nullptr || !wanted()) return std::nullopt;
  return std::string(kHugePageMallocTunable);
}

void StartAgainWithHugePageMalloc(char* const* argv, const std::function<bool()>& wanted) {
  const std::optional<std::string> tunables = HugePageMallocTunables(
      std::getenv("GLIBC_TUNABLES"), std::getenv(kHugePageMallocMarker), wanted);
  if (!tunables || argv == nullptr || argv[0] == nullptr) return;
  if (setenv("GLIBC_TUNABLES", tunables->c_str(), 1) != 0) return;
  if (setenv(kHugePageMallocMarker, "1", 1) == 0) execv("/proc/self/exe", argv);
  // exec failed (no /proc, say): go on as this process, environment restored.
  unsetenv("GLIBC_TUNABLES");
  unsetenv(kHugePageMallocMarker);
}

}  // namespace areagraph

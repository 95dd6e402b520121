#include "stages/common/huge_page_restart.h"

#include <unistd.h>

#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <optional>

namespace areagraph {
namespace {

constexpr char kTunablesVariable[] = "GLIBC_TUNABLES";
constexpr char kHugePageTunable[] = "glibc.malloc.hugetlb";

}  // namespace

bool HasHugePageTunable(const char* tunables) {
  return tunables != nullptr && std::strstr(tunables, kHugePageTunable) != nullptr;
}

std::string WithHugePageTunable(const char* tunables) {
  std::string value = tunables == nullptr ? "" : tunables;
  if (!value.empty()) value += ':';
  return value + kHugePageTunable + "=1";
}

bool MayRestartWithHugePageTunable() { return !HasHugePageTunable(std::getenv(kTunablesVariable)); }

void RestartWithHugePageTunable(char** argv) {
  const char* given = std::getenv(kTunablesVariable);
  const std::optional<std::string> before =
      given == nullptr ? std::nullopt : std::optional<std::string>(given);
  const std::string tunables = WithHugePageTunable(given);
  if (setenv(kTunablesVariable, tunables.c_str(), /*overwrite=*/1) != 0) return;
  // The link's target, not the link: the process keeps its name (ps, top).
  std::error_code error;
  const std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", error);
  if (!error) execv(self.c_str(), argv);
  // Not restarted: the environment goes back to what the user gave.
  if (before) {
    setenv(kTunablesVariable, before->c_str(), /*overwrite=*/1);
  } else {
    unsetenv(kTunablesVariable);
  }
}

}  // namespace areagraph

#include "common/process_setup/huge_page_restart.h"

#include <unistd.h>

#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <optional>

#include "common/png_header.h"

namespace areagraph {
namespace {

char** restart_command_line = nullptr;

constexpr char kTunablesVariable[] = "GLIBC_TUNABLES";
constexpr char kHugePageTunable[] = "glibc.malloc.hugetlb";

// The link's target, not the link: the process keeps its name (ps, top).
std::optional<std::filesystem::path> SelfExecutable() {
  std::error_code error;
  std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", error);
  if (error) return std::nullopt;
  return self;
}

std::optional<std::string> Variable(const char* name) {
  const char* value = std::getenv(name);
  return value == nullptr ? std::nullopt : std::optional<std::string>(value);
}

void Restore(const char* name, const std::optional<std::string>& value) {
  if (value) {
    setenv(name, value->c_str(), /*overwrite=*/1);
  } else {
    unsetenv(name);
  }
}

}  // namespace

bool IsBigMapImage(const std::string& path) {
  const std::optional<int64_t> pixels = PngFilePixels(path);
  return pixels && *pixels > kHugePageRestartPixels;
}

bool HasHugePageTunable(const char* tunables) {
  return tunables != nullptr && std::strstr(tunables, kHugePageTunable) != nullptr;
}

std::string WithHugePageTunable(const char* tunables) {
  std::string value = tunables == nullptr ? "" : tunables;
  if (!value.empty()) value += ':';
  return value + kHugePageTunable + "=1";
}

bool MayRestartWithHugePageTunable() {
  return !HasHugePageTunable(std::getenv(kTunablesVariable)) && !RestartedWithHugePageTunable();
}

bool RestartedWithHugePageTunable() {
  const std::optional<std::string> marker = Variable(kHugePageRestartVariable);
  if (!marker) return false;
  const std::optional<std::filesystem::path> self = SelfExecutable();
  return self && self->filename() == *marker;
}

std::string HugePageRestartLine(const std::string& tool) {
  if (!RestartedWithHugePageTunable()) return "";
  return tool + ": restarted with " + kHugePageTunable + "=1\n";
}

void SetRestartCommandLine(char** argv) { restart_command_line = argv; }

void RestartWithHugePageTunable() {
  const std::optional<std::filesystem::path> self = SelfExecutable();
  if (restart_command_line == nullptr || !self) return;
  const std::optional<std::string> tunables = Variable(kTunablesVariable);
  const std::optional<std::string> marker = Variable(kHugePageRestartVariable);
  const std::string value = WithHugePageTunable(std::getenv(kTunablesVariable));
  if (setenv(kTunablesVariable, value.c_str(), /*overwrite=*/1) == 0 &&
      setenv(kHugePageRestartVariable, self->filename().c_str(), /*overwrite=*/1) == 0) {
    execv(self->c_str(), restart_command_line);
  }
  // Not restarted: the environment goes back to what the user gave.
  Restore(kTunablesVariable, tunables);
  Restore(kHugePageRestartVariable, marker);
}

}  // namespace areagraph

#include "tools/store/store_text.h"

#include <cstdio>
#include <filesystem>

#include "store/store_maintenance.h"

namespace areagraph {

std::string Plural(int64_t count, const std::string& noun) {
  return std::to_string(count) + " " + noun + (count == 1 ? "" : "s");
}

std::string FormatBytes(int64_t bytes) {
  std::string text = Plural(bytes, "byte");
  if (bytes >= (1 << 20)) {
    char mib[32];
    std::snprintf(mib, sizeof(mib), " (%.1f MiB)", static_cast<double>(bytes) / (1 << 20));
    text += mib;
  }
  return text;
}

int64_t StoreFileBytes(const std::string& path) {
  std::error_code missing;
  int64_t bytes = 0;
  for (const std::string& file : {path, path + "-wal"}) {
    const auto size = std::filesystem::file_size(file, missing);
    if (!missing) bytes += static_cast<int64_t>(size);
  }
  return bytes;
}

std::string RemovedText(const MaintenanceCounts& removed) {
  if (removed.artifacts == 0 && removed.maps == 0) {
    return "nothing to remove: every artifact is reachable from a head";
  }
  return "removed " + Plural(removed.artifacts, "artifact") + " (" +
         FormatBytes(removed.payload_bytes) + " of payload) and " +
         Plural(removed.maps, "empty map");
}

void VacuumAndReport(const std::string& path, const std::string& name, std::ostream& out) {
  const int64_t before = StoreFileBytes(path);
  VacuumArtifactStore(path);
  out << "vacuumed " << name << ": " << FormatBytes(before) << " -> "
      << FormatBytes(StoreFileBytes(path)) << " on disk\n";
}

}  // namespace areagraph

#include "tools/inspect/history_report.h"

#include <cstdio>
#include <vector>

#include "common/error.h"
#include "common/json.h"
#include "common/text.h"
#include "proto/artifacts.pb.h"
#include "stages/pipeline/stage.h"

namespace areagraph {
namespace {

std::vector<VersionRecord> HistoryOf(ArtifactStore& store, const std::string& map_name) {
  if (!store.ReadMap(map_name)) throw InputError("map '" + map_name + "' is not in the store");
  std::vector<VersionRecord> versions = store.ReadVersions(map_name);
  if (versions.empty()) {
    throw InputError("map '" + map_name +
                     "' has no Area Graph versions yet; run ag-match (or ag-run) on it");
  }
  return versions;
}

bool IsNumber(const std::string& text) {
  return !text.empty() && text.size() < 18 &&
         text.find_first_not_of("0123456789") == std::string::npos;
}

}  // namespace

void PrintHistory(ArtifactStore& store, const std::string& map_name, std::ostream& out) {
  char line[512];
  std::snprintf(line, sizeof(line), "%7s  %-12s  %-24s  %-12s  %s\n", "version", "key",
                "created (UTC)", "predecessor", "graph");
  out << line;
  for (const VersionRecord& version : HistoryOf(store, map_name)) {
    std::string graph = "(no longer stored)";
    if (version.stored) {
      const std::optional<ArtifactRecord> row =
          store.ReadArtifactSummary(map_name, version.cache_key);
      graph = row ? row->summary_line : "";
      if (version.is_head) graph += "  (head)";
    }
    std::snprintf(line, sizeof(line), "%7lld  %-12s  %-24s  %-12s  %s\n",
                  static_cast<long long>(version.number), ShortKey(version.cache_key).c_str(),
                  version.created_at.c_str(),
                  version.predecessor_key.empty() ? "-" : ShortKey(version.predecessor_key).c_str(),
                  graph.c_str());
    out << line;
  }
}

std::string FindVersionKey(ArtifactStore& store, const std::string& map_name,
                           const std::string& version) {
  const std::vector<VersionRecord> versions = HistoryOf(store, map_name);
  std::vector<const VersionRecord*> found;
  for (const VersionRecord& record : versions) {
    if (version == "head" ? record.is_head
        : IsNumber(version)
            ? std::to_string(record.number) == version
            : record.cache_key.compare(0, version.size(), version) == 0 && !version.empty()) {
      found.push_back(&record);
    }
  }
  if (found.empty()) {
    throw InputError("map '" + map_name + "' has no version '" + version + "' (versions 1 to " +
                     std::to_string(versions.back().number) + ", or a key)");
  }
  if (found.size() > 1) {
    throw InputError("'" + version + "' names " + std::to_string(found.size()) +
                     " versions of map '" + map_name + "'; give a key (ag-inspect --history)");
  }
  if (!found[0]->stored) {
    throw InputError("version " + std::to_string(found[0]->number) + " of map '" + map_name +
                     "' is no longer stored (ag-store gc dropped it)");
  }
  return found[0]->cache_key;
}

void PrintVersionDiff(ArtifactStore& store, const std::string& map_name, const std::string& from,
                      const std::string& to, const DiffThresholds& thresholds, bool json,
                      std::ostream& out) {
  const std::string from_key = FindVersionKey(store, map_name, from);
  const std::string to_key = FindVersionKey(store, map_name, to);
  proto::AreaGraphDiff diff =
      DiffAreaGraphs(ReadArtifactAs<proto::AreaGraph>(store, map_name, from_key),
                     ReadArtifactAs<proto::AreaGraph>(store, map_name, to_key), thresholds);
  diff.set_map_name(map_name);
  diff.set_from_key(from_key);
  diff.set_to_key(to_key);
  if (json) {
    out << MessageToJson(diff) << "\n";
  } else {
    out << "map '" << map_name << "', " << ShortKey(from_key) << " -> " << ShortKey(to_key) << ", "
        << FormatAreaGraphDiff(diff);
  }
}

}  // namespace areagraph

#include "tools/report/run_report_writer.h"

#include <algorithm>
#include <iostream>
#include <memory>
#include <optional>
#include <vector>

#include "runner/run/map_collection.h"
#include "runner/run/shard.h"
#include "store/artifact_store.h"
#include "tools/report/collection_report.h"

namespace areagraph {

namespace {

// The maps a store holds and those it records as failed, sorted.
std::vector<std::string> StoreMapNames(const std::string& store_path) {
  const std::unique_ptr<ArtifactStore> store = OpenArtifactStore(store_path, StoreMode::kReadOnly);
  std::vector<std::string> names;
  for (const MapRecord& map : store->ReadAllMaps()) names.push_back(map.name);
  for (const FailureRecord& failure : store->ReadFailures()) names.push_back(failure.map_name);
  std::sort(names.begin(), names.end());
  names.erase(std::unique(names.begin(), names.end()), names.end());
  return names;
}

}  // namespace

void WriteRunReport(const RunFlags& flags, const std::string& dir) {
  std::optional<Shard> shard;
  if (!flags.shard.empty()) shard = ParseShard(flags.shard);
  std::vector<std::string> names;
  if (flags.maps.empty()) {
    names = StoreMapNames(flags.stage.store_path);
  } else {
    for (const MapEntry& entry : CollectMaps(flags.maps)) names.push_back(entry.name);
  }
  names.erase(
      std::remove_if(names.begin(), names.end(),
                     [&](const std::string& name) { return shard && !InShard(name, *shard); }),
      names.end());
  const CollectionReport report =
      WriteCollectionReport(flags.stage.store_path, names, dir, std::cerr);
  std::cerr << "ag-run: report: " << report.index_path << " (" << report.pages << " map pages, "
            << report.failed << " failed)\n";
}

}  // namespace areagraph

#include "tools/report/run_report_writer.h"

#include <iostream>
#include <optional>
#include <vector>

#include "runner/run/map_collection.h"
#include "runner/run/shard.h"
#include "tools/report/collection_report.h"

namespace areagraph {

void WriteRunReport(const RunFlags& flags, const std::string& dir) {
  std::optional<Shard> shard;
  if (!flags.shard.empty()) shard = ParseShard(flags.shard);
  std::vector<std::string> names;
  for (const MapEntry& entry : CollectMaps(flags.maps)) {
    if (!shard || InShard(entry.name, *shard)) names.push_back(entry.name);
  }
  const CollectionReport report =
      WriteCollectionReport(flags.stage.store_path, names, dir, std::cerr);
  std::cerr << "ag-run: report: " << report.index_path << " (" << report.pages << " map pages, "
            << report.failed << " failed)\n";
}

}  // namespace areagraph

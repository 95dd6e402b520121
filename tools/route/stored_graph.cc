#include "tools/route/stored_graph.h"

#include <optional>

#include "common/error.h"
#include "stages/pipeline/stage.h"
#include "stages/pipeline/stage_versions.h"
#include "tools/inspect/history_report.h"

namespace areagraph {

proto::AreaGraph ReadStoredAreaGraph(ArtifactStore& store, const std::string& map_name,
                                     const std::string& version) {
  if (!store.ReadMap(map_name)) throw InputError("map '" + map_name + "' is not in the store");
  if (!version.empty()) {
    return ReadArtifactAs<proto::AreaGraph>(store, map_name,
                                            FindVersionKey(store, map_name, version));
  }
  const std::optional<std::string> key = NewestGraphKey(store, map_name);
  if (!key) throw InputError("map '" + map_name + "' has no Area Graph; run ag-merge first");
  return ReadArtifactAs<proto::AreaGraph>(store, map_name, *key);
}

}  // namespace areagraph

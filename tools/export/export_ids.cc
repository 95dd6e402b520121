#include "tools/export/export_ids.h"

#include <unordered_set>

#include "common/error.h"

namespace areagraph {

ExportIds::ExportIds(const proto::AreaGraph& graph) : stable_(graph.has_version()) {
  std::unordered_set<int32_t> ids;
  for (const proto::Area& area : graph.areas()) {
    if (!ids.insert(Of(area)).second || !area_id_of_index_.emplace(area.id(), Of(area)).second) {
      throw InputError("the Area Graph has two areas with id " + std::to_string(Of(area)));
    }
  }
  ids.clear();
  for (const proto::Passage& passage : graph.passages()) {
    if (!ids.insert(Of(passage)).second) {
      throw InputError("the Area Graph has two passages with id " + std::to_string(Of(passage)));
    }
  }
}

int32_t ExportIds::Of(const proto::Area& area) const {
  return stable_ ? area.stable_id() : area.id();
}

int32_t ExportIds::Of(const proto::Passage& passage) const {
  return stable_ ? passage.stable_id() : passage.id();
}

int32_t ExportIds::OfArea(int32_t index) const {
  const auto found = area_id_of_index_.find(index);
  if (found == area_id_of_index_.end()) {
    throw InputError("a passage joins area " + std::to_string(index) +
                     ", which the Area Graph does not have");
  }
  return found->second;
}

std::string IdsKindName(const ExportIds& ids) { return ids.stable() ? "stable" : "index"; }

}  // namespace areagraph

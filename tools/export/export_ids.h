#pragma once

#include <cstdint>
#include <string>
#include <unordered_map>

#include "proto/artifacts.pb.h"

namespace areagraph {

// The ids every export keys areas and passages by. A graph from ag-match
// (one with a version) has stable ids, which stay with an area or passage
// across the map's versions, so files written before and after a re-run
// agree; exports use those. A graph without them (ag-merge's, when merge ran
// after match) gives its indices instead, which the next version renumbers,
// and each format says which it holds (IdsKindName). The index stays
// available beside the id in every format.
class ExportIds {
 public:
  // Throws InputError when two areas or two passages would get the same id.
  explicit ExportIds(const proto::AreaGraph& graph);

  bool stable() const { return stable_; }

  // The id of an area or passage of the graph.
  int32_t Of(const proto::Area& area) const;
  int32_t Of(const proto::Passage& passage) const;

  // The id of the area whose index (Area.id, as Passage.area_a and area_b
  // name it) is `index`. Throws InputError for an index no area has.
  int32_t OfArea(int32_t index) const;

 private:
  bool stable_;
  std::unordered_map<int32_t, int32_t> area_id_of_index_;
};

// "stable" or "index": what the ids of a graph's exports are.
std::string IdsKindName(const ExportIds& ids);

}  // namespace areagraph

#include "stages/match/graph_assembly.h"

#include <utility>

#include "stages/geometry/disjoint_sets.h"

namespace areagraph {

proto::AreaGraph AssembleGraph(const proto::AreaGraph& base, std::vector<proto::Area> areas,
                               std::vector<proto::Passage> passages) {
  proto::AreaGraph out = base;
  out.clear_areas();
  out.clear_passages();
  for (proto::Area& area : areas) {
    proto::Area* added = out.add_areas();
    *added = std::move(area);
    added->set_id(out.areas_size() - 1);
    added->clear_passage_ids();
  }
  for (proto::Passage& passage : passages) {
    proto::Passage* kept = out.add_passages();
    *kept = std::move(passage);
    kept->set_id(out.passages_size() - 1);
    out.mutable_areas(kept->area_a())->add_passage_ids(kept->id());
    out.mutable_areas(kept->area_b())->add_passage_ids(kept->id());
  }
  DisjointSets components(out.areas_size());
  int count = out.areas_size();
  for (const proto::Passage& passage : out.passages()) {
    if (components.Union(passage.area_a(), passage.area_b())) --count;
  }
  out.set_components(count);
  return out;
}

}  // namespace areagraph

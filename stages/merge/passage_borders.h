#pragma once

#include <vector>

#include "stages/merge/passage_finder.h"
#include "stages/merge/planar_partition.h"

namespace areagraph {

// A passage and the border chain it opens (-1: its two areas share none).
struct PassageOnBorder {
  PassagePlan passage;
  int chain = -1;
};

// Puts every passage on the border between its two areas: of the chains
// between them (areas are labelled `label_of_area[id]` in the partition), the
// one nearest to the passage point. Passages that land on one chain are one
// opening, and the narrowest of them is kept. A passage whose two areas share
// no border (at a junction of three areas, the two that only meet at a
// point) is dropped when the passages that do lie on borders connect its
// areas anyway. Otherwise the raster gave the cells at the opening to a
// third area, and the passage moves to the nearest free border (within its
// width) between one of its areas and another one, as long as that keeps its
// two areas connected; failing that it stays without a chain. The order of
// `passages` is kept.
std::vector<PassageOnBorder> PlacePassagesOnBorders(const std::vector<PassagePlan>& passages,
                                                    const PlanarPartition& partition,
                                                    const std::vector<int>& label_of_area);

}  // namespace areagraph

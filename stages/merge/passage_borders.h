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
// opening, and the narrowest of them is kept. The order of `passages` is kept.
std::vector<PassageOnBorder> PlacePassagesOnBorders(const std::vector<PassagePlan>& passages,
                                                    const PlanarPartition& partition,
                                                    const std::vector<int>& label_of_area);

}  // namespace areagraph

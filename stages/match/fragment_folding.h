#pragma once

#include <vector>

#include "proto/artifacts.pb.h"
#include "stages/match/area_cells.h"

namespace areagraph {

// A new area counts as a piece split off a previous area when at least this
// share of its cells lay in that one area. Chosen on a real map's
// simulated exploration (tools/bench-live.sh) with the constructed growing
// maps of tests/stages/match; see docs/performance.md, "Match's constants".
inline constexpr double kFragmentInsideShare = 0.8;

// One area folded into a neighbour: indices in the graph.
struct AreaFold {
  int fragment = 0;
  int into = 0;
};

// The areas of `current` that scan noise split off an area of `previous`:
// an area that took no previous id (`ids[i]` < 0, see MatchAreaGraph),
// smaller than `max_m2`, with kFragmentInsideShare of
// its cells (`cells` of `current`; `overlaps` from CountOverlaps(previous's cells, `cells`)) inside
// one previous area whose id went to an area it borders. Each goes back into that area. ag-merge's
// thresholds (merge.min_area_m2 above all) cut such pieces off in one update and fold them back in
// the next, and every round trip would cost the piece's id; a piece that is really new (newly seen
// space) or large stays an area of its own.
std::vector<AreaFold> FindNoiseFragments(const proto::AreaGraph& current,
                                         const proto::AreaGraph& previous,
                                         const std::vector<int>& ids, const AreaCells& cells,
                                         const std::vector<AreaOverlap>& overlaps, double max_m2);

// `graph` with each fold's fragment joined to its `into` area: one polygon
// (the border they shared dropped, see UnionOfNeighbours), summed area,
// area-weighted centroid, both areas' topology edges, the kind of `into`.
// Passages between the two go; the fragment's other passages now join
// `into`. Areas and passages are numbered again in order. A fold whose
// polygons do not join into one is skipped. `folded` (optional) counts the
// folds done.
proto::AreaGraph FoldAreas(const proto::AreaGraph& graph, const std::vector<AreaFold>& folds,
                           int* folded = nullptr);

}  // namespace areagraph

#include "stages/match/area_graph_matching.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <tuple>
#include <utility>
#include <vector>

#include "common/error.h"
#include "stages/common/pipeline_options.h"
#include "stages/common/skipped_passes.h"
#include "stages/match/area_cells.h"
#include "stages/match/fragment_folding.h"
#include "stages/match/join_undoing.h"
#include "store/digest.h"

namespace areagraph {
namespace {

// The stable ids of a matched graph's areas, by area index.
std::vector<int> StableAreaIds(const proto::AreaGraph& graph) {
  std::vector<int> ids;
  for (const proto::Area& area : graph.areas()) ids.push_back(area.stable_id());
  return ids;
}

// Gives each area of `current` the stable id of the previous area it matches
// (or -1); see MatchAreaGraph. `after`: current's cells; `overlaps`: with
// the previous graph's cells, as CountOverlaps gives them.
std::vector<int> MatchAreas(const proto::AreaGraph& current, const proto::AreaGraph& previous,
                            const AreaCells& after, const AreaCells& before,
                            const std::vector<AreaOverlap>& overlaps, double min_overlap) {
  std::vector<AreaOverlap> pairs;
  for (const AreaOverlap& pair : overlaps) {
    const int64_t smaller = std::min(before.cells[pair.before], after.cells[pair.after]);
    if (pair.cells >= min_overlap * smaller) pairs.push_back(pair);
  }
  // Largest overlaps first; ties by the ids, so the result never depends on
  // the order of the pairs.
  std::sort(pairs.begin(), pairs.end(), [&](const AreaOverlap& a, const AreaOverlap& b) {
    return std::make_tuple(-a.cells, previous.areas(a.before).stable_id(), a.after) <
           std::make_tuple(-b.cells, previous.areas(b.before).stable_id(), b.after);
  });
  std::vector<int> ids(current.areas_size(), -1);
  std::vector<bool> used(previous.areas_size(), false);
  for (const AreaOverlap& pair : pairs) {
    if (used[pair.before] || ids[pair.after] >= 0) continue;
    used[pair.before] = true;
    ids[pair.after] = previous.areas(pair.before).stable_id();
  }
  return ids;
}

// Matches the areas of `current` to `previous`, first folding the pieces
// that noise split off a previous area back into it (FindNoiseFragments;
// again while folds make more of them, as when a piece only borders another
// piece), then cutting apart the joins of two previous areas
// (FindUndoableJoins, in rounds until one cuts nothing, since each round
// cuts one previous area out of each joined area; the pieces are matched and
// folded again; no more rounds than previous areas, as each round gives one
// back):
// `current` becomes the graph that is published, and the result is its
// areas' previous ids (or -1).
std::vector<int> MatchAreasFoldingFragments(proto::AreaGraph& current,
                                            const proto::AreaGraph& previous,
                                            const proto::MatchOptions& options, bool fold) {
  const AreaCells before = RasterizeAreas(previous, current.frame());
  int rounds_left = !fold || options.split_joins_below_m2() <= 0 ? 0 : previous.areas_size();
  while (true) {
    const AreaCells after = RasterizeAreas(current, current.frame());
    const std::vector<AreaOverlap> overlaps = CountOverlaps(before, after);
    std::vector<int> ids =
        MatchAreas(current, previous, after, before, overlaps, options.min_overlap());
    if (!fold) return ids;
    if (options.fold_fragments_below_m2() > 0) {
      const std::vector<AreaFold> folds = FindNoiseFragments(
          current, previous, ids, after, overlaps, options.fold_fragments_below_m2());
      int folded = 0;
      if (!folds.empty()) current = FoldAreas(current, folds, &folded);
      if (folded > 0) continue;
    }
    if (rounds_left <= 0) return ids;
    --rounds_left;
    const std::vector<AreaUnjoin> unjoins = FindUndoableJoins(
        previous, ids, before, overlaps, options.split_joins_below_m2(), options.min_overlap(),
        RunsStagePass(options, proto::MatchOptions::UNDO_JOINS_WHEN_ID_MOVED),
        RunsStagePass(options, proto::MatchOptions::UNDO_JOINS_WITHOUT_PASSAGE));
    int split = 0;
    if (!unjoins.empty()) {
      current = SplitJoinedAreas(current, previous, unjoins, options, &split);
    }
    if (split == 0) return ids;
  }
}

// The two stable area ids a passage joins, smaller first.
std::pair<int, int> PassageEnds(const proto::Passage& passage, const std::vector<int>& area_ids) {
  const int a = area_ids.at(passage.area_a()), b = area_ids.at(passage.area_b());
  return {std::min(a, b), std::max(a, b)};
}

double Distance(const proto::Point2& a, const proto::Point2& b) {
  return std::hypot(a.x() - b.x(), a.y() - b.y());
}

// Gives each passage of `current` the stable id of the previous passage it
// matches (or -1): same two stable areas, nearest first, within max_shift_m.
std::vector<int> MatchPassages(const proto::AreaGraph& current,
                               const std::vector<int>& current_area_ids,
                               const proto::AreaGraph& previous, double max_shift_m) {
  const std::vector<int> previous_area_ids = StableAreaIds(previous);
  std::vector<std::tuple<double, int, int>> pairs;  // distance, previous id, current index
  std::map<std::pair<int, int>, std::vector<int>> previous_by_ends;
  for (int i = 0; i < previous.passages_size(); ++i) {
    previous_by_ends[PassageEnds(previous.passages(i), previous_area_ids)].push_back(i);
  }
  for (int c = 0; c < current.passages_size(); ++c) {
    const proto::Passage& passage = current.passages(c);
    const auto found = previous_by_ends.find(PassageEnds(passage, current_area_ids));
    if (found == previous_by_ends.end()) continue;
    for (int p : found->second) {
      const double shift = Distance(previous.passages(p).point_m(), passage.point_m());
      if (shift <= max_shift_m) pairs.emplace_back(shift, previous.passages(p).stable_id(), c);
    }
  }
  std::sort(pairs.begin(), pairs.end());
  std::vector<int> ids(current.passages_size(), -1);
  std::set<int> used;
  for (const auto& [shift, previous_id, c] : pairs) {
    if (ids[c] >= 0 || !used.insert(previous_id).second) continue;
    ids[c] = previous_id;
  }
  return ids;
}

// Gives every -1 in `ids` the next unused id, in order.
void NumberNewOnes(std::vector<int>& ids, int32_t& next_id) {
  for (int& id : ids) {
    if (id < 0) id = next_id++;
  }
}

void CheckIsMatched(const proto::AreaGraph& previous) {
  if (!previous.has_version()) {
    throw InputError("the previous version has no stable ids (it is not a match artifact)");
  }
  for (const proto::Passage& passage : previous.passages()) {
    if (passage.area_a() < 0 || passage.area_a() >= previous.areas_size() || passage.area_b() < 0 ||
        passage.area_b() >= previous.areas_size()) {
      throw InputError("a passage of the previous version joins an area it does not have");
    }
  }
}

}  // namespace

proto::AreaGraph MatchAreaGraph(const proto::AreaGraph& current, const proto::AreaGraph* previous,
                                const VersionLink& version, const proto::MatchOptions& options,
                                const std::string& segmentation_options_digest) {
  for (const proto::Passage& passage : current.passages()) {
    if (passage.area_a() < 0 || passage.area_a() >= current.areas_size() || passage.area_b() < 0 ||
        passage.area_b() >= current.areas_size()) {
      throw InputError("passage " + std::to_string(passage.id()) +
                       " joins an area that is not in the graph");
    }
  }
  proto::AreaGraph matched = current;
  std::vector<int> area_ids(current.areas_size(), -1);
  int32_t next_area_id = 0, next_passage_id = 0;
  if (previous != nullptr) {
    CheckIsMatched(*previous);
    if (!current.has_robot_width_m()) {
      throw InputError(
          "the Area Graph holds no robot width (written by merge 19 or older): run "
          "ag-merge again");
    }
    const bool same_segmentation =
        previous->version().segmentation_options_digest() == segmentation_options_digest;
    area_ids = MatchAreasFoldingFragments(matched, *previous, options, same_segmentation);
    next_area_id = previous->version().next_area_id();
    next_passage_id = previous->version().next_passage_id();
  }
  NumberNewOnes(area_ids, next_area_id);
  std::vector<int> passage_ids(matched.passages_size(), -1);
  if (previous != nullptr) {
    passage_ids = MatchPassages(matched, area_ids, *previous, options.passage_max_shift_m());
  }
  NumberNewOnes(passage_ids, next_passage_id);

  for (int i = 0; i < matched.areas_size(); ++i)
    matched.mutable_areas(i)->set_stable_id(area_ids[i]);
  for (int i = 0; i < matched.passages_size(); ++i) {
    matched.mutable_passages(i)->set_stable_id(passage_ids[i]);
  }
  proto::AreaGraphVersion* place = matched.mutable_version();
  place->set_number(version.number);
  place->set_predecessor_key(version.predecessor_key);
  place->set_next_area_id(next_area_id);
  place->set_next_passage_id(next_passage_id);
  if (!segmentation_options_digest.empty()) {
    place->set_segmentation_options_digest(segmentation_options_digest);
  }
  return matched;
}

std::string SegmentationOptionsDigest(const proto::PipelineOptions& options) {
  proto::PipelineOptions segmentation = options;
  segmentation.clear_match();
  return Sha256Hex(CanonicalText(segmentation));
}

}  // namespace areagraph

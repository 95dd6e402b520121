#include "stages/match/area_graph_diff.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <sstream>

#include "common/error.h"
#include "stages/match/area_cells.h"

namespace areagraph {
namespace {

void CheckHasStableIds(const proto::AreaGraph& graph, const char* which) {
  if (!graph.has_version()) {
    throw InputError(std::string("the ") + which +
                     " graph has no stable ids; diffs compare versions made by ag-match");
  }
}

// For each area of `from`, the area of `to` holding most of its cells when
// that is at least half of them, else -1 (indices).
std::vector<int> WhereMostWent(const std::vector<AreaOverlap>& overlaps, bool from_before,
                               const std::vector<int64_t>& from_cells) {
  std::vector<int> target(from_cells.size(), -1);
  std::vector<int64_t> best(from_cells.size(), 0);
  for (const AreaOverlap& overlap : overlaps) {
    const int from = from_before ? overlap.before : overlap.after;
    const int to = from_before ? overlap.after : overlap.before;
    if (overlap.cells > best[from]) {
      best[from] = overlap.cells;
      target[from] = to;
    }
  }
  for (size_t i = 0; i < target.size(); ++i) {
    if (2 * best[i] < from_cells[i]) target[i] = -1;
  }
  return target;
}

std::set<int> PassagesOf(const proto::AreaGraph& graph, int area) {
  std::set<int> ids;
  for (const proto::Passage& passage : graph.passages()) {
    if (passage.area_a() == area || passage.area_b() == area) ids.insert(passage.stable_id());
  }
  return ids;
}

void DiffPassages(const proto::AreaGraph& before, const proto::AreaGraph& after,
                  const DiffThresholds& thresholds, proto::AreaGraphDiff& diff) {
  std::map<int, const proto::Passage*> old_ones;
  for (const proto::Passage& passage : before.passages()) old_ones[passage.stable_id()] = &passage;
  std::set<int> kept;
  for (const proto::Passage& passage : after.passages()) {
    const auto found = old_ones.find(passage.stable_id());
    if (found == old_ones.end()) {
      diff.add_added_passages(passage.stable_id());
      continue;
    }
    kept.insert(passage.stable_id());
    const proto::Passage& old = *found->second;
    const double moved = std::hypot(passage.point_m().x() - old.point_m().x(),
                                    passage.point_m().y() - old.point_m().y());
    if (moved > thresholds.passage_m ||
        std::abs(passage.width_m() - old.width_m()) > thresholds.size * old.width_m()) {
      proto::PassageChange* change = diff.add_changed_passages();
      change->set_stable_id(passage.stable_id());
      change->set_moved_m(moved);
      change->set_width_before_m(old.width_m());
      change->set_width_after_m(passage.width_m());
    } else {
      diff.add_unchanged_passages(passage.stable_id());
    }
  }
  for (const auto& [id, passage] : old_ones) {
    if (kept.count(id) == 0) diff.add_removed_passages(id);
  }
  std::sort(diff.mutable_added_passages()->begin(), diff.mutable_added_passages()->end());
  std::sort(diff.mutable_unchanged_passages()->begin(), diff.mutable_unchanged_passages()->end());
  std::sort(diff.mutable_changed_passages()->begin(), diff.mutable_changed_passages()->end(),
            [](const proto::PassageChange& a, const proto::PassageChange& b) {
              return a.stable_id() < b.stable_id();
            });
}

}  // namespace

proto::AreaGraphDiff DiffAreaGraphs(const proto::AreaGraph& before, const proto::AreaGraph& after,
                                    const DiffThresholds& thresholds) {
  CheckHasStableIds(before, "older");
  CheckHasStableIds(after, "newer");
  proto::AreaGraphDiff diff;
  diff.set_from_version(before.version().number());
  diff.set_to_version(after.version().number());
  diff.set_size_threshold(thresholds.size);
  diff.set_passage_threshold_m(thresholds.passage_m);

  const AreaCells new_cells = RasterizeAreas(after, after.frame());
  const AreaCells old_cells = RasterizeAreas(before, after.frame());
  const std::vector<AreaOverlap> overlaps = CountOverlaps(old_cells, new_cells);
  const std::vector<int> old_went = WhereMostWent(overlaps, true, old_cells.cells);
  const std::vector<int> new_came = WhereMostWent(overlaps, false, new_cells.cells);
  std::map<int, int> old_index, new_index;  // stable id -> index
  for (int i = 0; i < before.areas_size(); ++i) old_index[before.areas(i).stable_id()] = i;
  for (int i = 0; i < after.areas_size(); ++i) new_index[after.areas(i).stable_id()] = i;

  std::map<int, std::vector<int>> split_into, merged_from;  // by kept stable id
  for (const auto& [id, i] : new_index) {
    if (old_index.count(id) > 0) continue;
    const int from = new_came[i] < 0 ? -1 : before.areas(new_came[i]).stable_id();
    diff.add_added_areas(id);
    diff.add_added_from(from);
    if (new_index.count(from) > 0) split_into[from].push_back(id);
  }
  for (const auto& [id, i] : old_index) {
    if (new_index.count(id) > 0) continue;
    const int into = old_went[i] < 0 ? -1 : after.areas(old_went[i]).stable_id();
    diff.add_removed_areas(id);
    diff.add_removed_into(into);
    if (old_index.count(into) > 0) merged_from[into].push_back(id);
  }
  const double cell_m2 = new_cells.resolution_m * new_cells.resolution_m;
  for (const auto& [id, i] : new_index) {
    const auto old = old_index.find(id);
    if (old == old_index.end()) continue;
    proto::AreaChange change;
    change.set_stable_id(id);
    const double cells_before = old_cells.cells[old->second];
    const double cells_after = new_cells.cells[i];
    change.set_area_before_m2(cells_before * cell_m2);
    change.set_area_after_m2(cells_after * cell_m2);
    change.set_grown(cells_after - cells_before > thresholds.size * cells_before);
    change.set_shrunk(cells_before - cells_after > thresholds.size * cells_before);
    for (int part : split_into[id]) change.add_split_into(part);
    for (int parent : merged_from[id]) change.add_merged_from(parent);
    change.set_kind_changed(before.areas(old->second).kind() != after.areas(i).kind());
    change.set_passages_changed(PassagesOf(before, old->second) != PassagesOf(after, i));
    if (change.grown() || change.shrunk() || change.split_into_size() > 0 ||
        change.merged_from_size() > 0 || change.kind_changed() || change.passages_changed()) {
      *diff.add_changed_areas() = change;
    } else {
      diff.add_unchanged_areas(id);
    }
  }
  DiffPassages(before, after, thresholds, diff);
  return diff;
}

namespace {

std::string IdList(const google::protobuf::RepeatedField<int32_t>& ids) {
  std::string text;
  for (int id : ids) text += (text.empty() ? "" : ", ") + std::to_string(id);
  return text;
}

std::string Describe(const proto::AreaChange& change) {
  std::ostringstream text;
  text.precision(1);
  text << std::fixed;
  std::vector<std::string> parts;
  if (change.split_into_size() > 0) parts.push_back("split off " + IdList(change.split_into()));
  if (change.merged_from_size() > 0) parts.push_back("took in " + IdList(change.merged_from()));
  if (change.grown()) parts.push_back("grown");
  if (change.shrunk()) parts.push_back("shrunk");
  if (change.kind_changed()) parts.push_back("kind changed");
  if (change.passages_changed()) parts.push_back("passages changed");
  for (size_t i = 0; i < parts.size(); ++i) text << (i > 0 ? ", " : "") << parts[i];
  text << " (" << change.area_before_m2() << " -> " << change.area_after_m2() << " m2)";
  return text.str();
}

}  // namespace

std::string FormatAreaGraphDiff(const proto::AreaGraphDiff& diff) {
  std::ostringstream out;
  out.precision(2);
  out << std::fixed;
  out << "version " << diff.from_version() << " -> " << diff.to_version() << ": areas "
      << diff.added_areas_size() << " added, " << diff.removed_areas_size() << " removed, "
      << diff.changed_areas_size() << " changed, " << diff.unchanged_areas_size()
      << " unchanged; passages " << diff.added_passages_size() << " added, "
      << diff.removed_passages_size() << " removed, " << diff.changed_passages_size()
      << " changed, " << diff.unchanged_passages_size() << " unchanged\n";
  for (int i = 0; i < diff.added_areas_size(); ++i) {
    out << "  + area " << diff.added_areas(i);
    if (diff.added_from(i) >= 0) out << " (from area " << diff.added_from(i) << ")";
    out << "\n";
  }
  for (int i = 0; i < diff.removed_areas_size(); ++i) {
    out << "  - area " << diff.removed_areas(i);
    if (diff.removed_into(i) >= 0) out << " (into area " << diff.removed_into(i) << ")";
    out << "\n";
  }
  for (const proto::AreaChange& change : diff.changed_areas()) {
    out << "  ~ area " << change.stable_id() << ": " << Describe(change) << "\n";
  }
  for (int id : diff.added_passages()) out << "  + passage " << id << "\n";
  for (int id : diff.removed_passages()) out << "  - passage " << id << "\n";
  for (const proto::PassageChange& change : diff.changed_passages()) {
    out << "  ~ passage " << change.stable_id() << ": moved " << change.moved_m() << " m, width "
        << change.width_before_m() << " -> " << change.width_after_m() << " m\n";
  }
  return out.str();
}

}  // namespace areagraph

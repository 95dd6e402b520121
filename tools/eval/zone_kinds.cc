#include "tools/eval/zone_kinds.h"

#include <filesystem>
#include <fstream>
#include <sstream>

#include "common/error.h"

namespace areagraph {

std::string KindsPathFor(const std::string& image_path) {
  const std::filesystem::path path(image_path);
  return (path.parent_path() / (path.stem().string() + ".kinds.tsv")).string();
}

ZoneKinds ReadZoneKinds(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw InputError("cannot read the kinds file '" + path + "'");
  std::string line;
  if (!std::getline(in, line) || line != "label\tkind") {
    throw InputError("the kinds file '" + path + "' does not start with 'label<TAB>kind'");
  }
  ZoneKinds kinds;
  for (int number = 2; std::getline(in, line); ++number) {
    if (line.empty()) continue;
    std::istringstream fields(line);
    int label = 0;
    std::string kind, rest;
    if (!(fields >> label) || !(fields >> kind) || (fields >> rest) || label <= 0 ||
        (kind != "room" && kind != "corridor" && kind != "dead_end")) {
      throw InputError("line " + std::to_string(number) + " of the kinds file '" + path +
                       "' is not '<label> <room|corridor|dead_end>'");
    }
    kinds[label] = kind;
  }
  return kinds;
}

std::optional<double> KindAccuracy(const ZoneOverlaps& counts, const ZoneKinds& result,
                                   const ZoneKinds& gt) {
  // The GT zone with a kind that each result zone overlaps most.
  std::map<int, std::pair<int, int64_t>> best;  // result label -> (gt label, overlap)
  for (const auto& [pair, pixels] : counts.overlap) {
    const auto& [result_label, gt_label] = pair;
    if (result.count(result_label) == 0 || gt.count(gt_label) == 0) continue;
    auto [it, added] = best.emplace(result_label, std::make_pair(gt_label, pixels));
    if (!added && pixels > it->second.second) it->second = {gt_label, pixels};
  }
  int64_t right = 0, all = 0;
  for (const auto& [result_label, match] : best) {
    const int64_t weight = counts.result_scored.at(result_label);
    const std::string& found = result.at(result_label);
    const std::string& truth = gt.at(match.first);
    all += weight;
    if (found == truth || (found == "dead_end" && truth == "corridor")) right += weight;
  }
  if (all == 0) return std::nullopt;
  return static_cast<double>(right) / static_cast<double>(all);
}

}  // namespace areagraph

#include "tools/eval/per_zone_mcc.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

#include "common/error.h"

namespace areagraph {

MccVariant ParseMccVariant(const std::string& name) {
  if (name == "standard") return MccVariant::kStandard;
  if (name == "maoris") return MccVariant::kMaoris;
  throw OptionsError("unknown MCC variant '" + name + "'; use standard or maoris");
}

double MatthewsCorrelation(double tp, double fp, double fn, double tn) {
  const double denominator = (tp + fp) * (tp + fn) * (tn + fp) * (tn + fn);
  if (denominator <= 0) return (fp == 0 && fn == 0) ? 1.0 : 0.0;
  return (tp * tn - fp * fn) / std::sqrt(denominator);
}

namespace {

struct Candidate {
  int gt;
  int64_t overlap;
};

// A result zone with the GT zones it touches, biggest overlap first.
struct ResultZone {
  int label;
  std::vector<Candidate> candidates;
};

std::vector<ResultZone> SortedResultZones(const ZoneOverlaps& counts) {
  std::map<int, std::vector<Candidate>> by_result;
  for (const auto& [pair, pixels] : counts.overlap) {
    by_result[pair.first].push_back({pair.second, pixels});
  }
  std::vector<ResultZone> zones;
  for (auto& [label, candidates] : by_result) {
    // Ties go to the smaller label (the maps are in label order already).
    std::stable_sort(candidates.begin(), candidates.end(),
                     [](const Candidate& a, const Candidate& b) { return a.overlap > b.overlap; });
    zones.push_back({label, std::move(candidates)});
  }
  std::stable_sort(zones.begin(), zones.end(), [](const ResultZone& a, const ResultZone& b) {
    return a.candidates.front().overlap > b.candidates.front().overlap;
  });
  return zones;
}

ZoneMatch ScoreMatch(const ZoneOverlaps& counts, int result, int gt, MccVariant variant) {
  ZoneMatch match;
  match.result = result;
  match.gt = gt;
  match.tp = counts.overlap.at({result, gt});
  match.fp = counts.result_scored.at(result) - match.tp;
  match.fn = counts.gt_scored.at(gt) - match.tp;
  const int64_t n = counts.scored_pixels;
  match.tn = variant == MccVariant::kStandard ? n - match.tp - match.fp - match.fn
                                              : n - (match.fp - counts.gt_scored.at(gt));
  match.mcc = MatthewsCorrelation(match.tp, match.fp, match.fn, match.tn);
  return match;
}

}  // namespace

PerZoneMcc ComputePerZoneMcc(const ZoneOverlaps& counts, MccVariant variant) {
  PerZoneMcc result;
  const std::vector<ResultZone> zones = SortedResultZones(counts);
  std::set<int> matched_gt;
  for (const ResultZone& zone : zones) {
    const Candidate* chosen = nullptr;
    for (const Candidate& candidate : zone.candidates) {
      if (matched_gt.count(candidate.gt) == 0) {
        chosen = &candidate;
        break;
      }
    }
    if (chosen == nullptr && variant == MccVariant::kMaoris) chosen = &zone.candidates.back();
    if (chosen == nullptr) {
      ++result.unmatched_result_zones;
      continue;
    }
    matched_gt.insert(chosen->gt);
    result.matches.push_back(ScoreMatch(counts, zone.label, chosen->gt, variant));
  }
  if (variant == MccVariant::kStandard) {
    for (const auto& [gt, pixels] : counts.gt_scored) {
      if (matched_gt.count(gt) == 0) ++result.unmatched_gt_zones;
    }
  } else {
    for (const ResultZone& zone : zones) {
      for (const Candidate& candidate : zone.candidates) {
        if (matched_gt.count(candidate.gt) == 0) ++result.unmatched_gt_zones;
      }
    }
  }
  const size_t entries =
      result.matches.size() + result.unmatched_result_zones + result.unmatched_gt_zones;
  double sum = 0;
  for (const ZoneMatch& match : result.matches) sum += match.mcc;
  result.mean = entries == 0 ? 0.0 : sum / static_cast<double>(entries);
  return result;
}

}  // namespace areagraph

#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "tools/eval/zone_overlaps.h"

namespace areagraph {

// Which reading of MAORIS' compareImagesUnbiased to compute.
enum class MccVariant {
  // Greedy matching as MAORIS does it, each GT zone matched at most once,
  // unmatched zones counted once each, and the standard TN = N - TP - FP - FN.
  kStandard,
  // MAORIS' code as published, for cross-checking its numbers: TN = N - (FP -
  // |gt zone|); a result zone whose GT candidates are all taken is still
  // matched to its last (smallest) candidate; an unmatched GT zone counts once
  // per result zone that touches it.
  kMaoris,
};

// "standard" or "maoris".
MccVariant ParseMccVariant(const std::string& name);

// One result zone paired with one GT zone, with its confusion counts over the
// scored pixels (N = pixels in a segment in both images).
struct ZoneMatch {
  int result = 0;
  int gt = 0;
  int64_t tp = 0, fp = 0, fn = 0, tn = 0;
  double mcc = 0;
};

struct PerZoneMcc {
  // Mean over the matches and the unmatched zones, which score 0.
  double mean = 0;
  std::vector<ZoneMatch> matches;
  int unmatched_result_zones = 0;
  int unmatched_gt_zones = 0;
};

// MAORIS' per-zone MCC. Result zones are taken in order of their largest
// overlap with any GT zone (biggest first); each is matched to the GT zone it
// overlaps most among those not yet matched. Per match: TP = overlap, FP =
// rest of the result zone, FN = rest of the GT zone (all counted over scored
// pixels only). The score is the mean MCC over matches, with every unmatched
// zone adding a 0. An undefined MCC (a zero factor in the denominator) is 1
// when FP = FN = 0, else 0. No scored pixels at all gives 0.
PerZoneMcc ComputePerZoneMcc(const ZoneOverlaps& counts, MccVariant variant);

// Matthews correlation coefficient, with the convention above for 0/0.
double MatthewsCorrelation(double tp, double fp, double fn, double tn);

}  // namespace areagraph

#include "tools/eval/precision_recall.h"

#include <algorithm>

#include "tools/eval/ground_truth.h"

namespace areagraph {

namespace {

bool IsBigEnough(const std::map<int, int64_t>& sizes, int label) {
  return sizes.at(label) > kSmallSegmentPixels;
}

}  // namespace

PrecisionRecall ComputePrecisionRecall(const ZoneOverlaps& counts) {
  std::map<int, int64_t> best_for_result, best_for_gt;
  for (const auto& [label, pixels] : counts.result_total) {
    if (pixels > kSmallSegmentPixels) best_for_result[label] = 0;
  }
  for (const auto& [label, pixels] : counts.gt_total) {
    if (pixels > kSmallSegmentPixels) best_for_gt[label] = 0;
  }
  for (const auto& [pair, pixels] : counts.overlap) {
    const auto [result, gt] = pair;
    if (!IsBigEnough(counts.result_total, result) || !IsBigEnough(counts.gt_total, gt)) continue;
    best_for_result[result] = std::max(best_for_result[result], pixels);
    best_for_gt[gt] = std::max(best_for_gt[gt], pixels);
  }
  PrecisionRecall scores;
  scores.result_segments = static_cast<int>(best_for_result.size());
  scores.gt_segments = static_cast<int>(best_for_gt.size());
  for (const auto& [label, best] : best_for_result) {
    scores.precision += static_cast<double>(best) / counts.result_total.at(label);
  }
  for (const auto& [label, best] : best_for_gt) {
    scores.recall += static_cast<double>(best) / counts.gt_total.at(label);
  }
  if (scores.result_segments > 0) scores.precision /= scores.result_segments;
  if (scores.gt_segments > 0) scores.recall /= scores.gt_segments;
  return scores;
}

}  // namespace areagraph

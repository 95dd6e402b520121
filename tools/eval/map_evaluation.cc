#include "tools/eval/map_evaluation.h"

#include <cmath>
#include <filesystem>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "tools/eval/ground_truth_alignment.h"
#include "tools/eval/label_image.h"
#include "tools/eval/precision_recall.h"
#include "tools/eval/zone_kinds.h"
#include "tools/eval/zone_overlaps.h"

namespace areagraph {
namespace {

bool SameShape(const cv::Size& a, const cv::Size& b) {
  const double ratio_a = static_cast<double>(a.width) / a.height;
  const double ratio_b = static_cast<double>(b.width) / b.height;
  return std::abs(ratio_a / ratio_b - 1) <= 0.01;
}

}  // namespace

MapEvaluation ScoreLabelImages(const cv::Mat& result_labels, const cv::Mat& gt_labels,
                               MccVariant variant) {
  return ScoreZoneOverlaps(CountZoneOverlaps(result_labels, gt_labels), variant);
}

MapEvaluation ScoreZoneOverlaps(const ZoneOverlaps& counts, MccVariant variant) {
  const PerZoneMcc mcc = ComputePerZoneMcc(counts, variant);
  const PrecisionRecall precision_recall = ComputePrecisionRecall(counts);
  MapEvaluation evaluation;
  evaluation.mcc = mcc.mean;
  evaluation.precision = precision_recall.precision;
  evaluation.recall = precision_recall.recall;
  evaluation.result_segments = static_cast<int>(counts.result_total.size());
  evaluation.gt_segments = static_cast<int>(counts.gt_total.size());
  evaluation.scored_pixels = counts.scored_pixels;
  return evaluation;
}

cv::Mat ReadGroundTruthLabels(const std::string& path, GroundTruthStyle* style) {
  const cv::Mat raw = ReadImageFile(path);
  if (*style == GroundTruthStyle::kAuto) *style = DetectGroundTruthStyle(raw);
  cv::Mat grey;
  if (*style == GroundTruthStyle::kLines || *style == GroundTruthStyle::kMaorisLines) {
    // The way Bormann's and MAORIS' evaluations load it.
    grey = ReadImageFile(path, cv::IMREAD_GRAYSCALE);
  }
  return GroundTruthLabels(raw, grey, *style);
}

MapEvaluation EvaluateMap(const std::string& result_path, const std::string& gt_path,
                          const EvaluationOptions& options) {
  cv::Mat result_labels = ReadSegmentationLabels(result_path, options.reading);
  if (options.drop_result_segments_px > 0) {
    DropSmallSegments(&result_labels, options.drop_result_segments_px);
  }
  GroundTruthStyle style = options.gt_style;
  cv::Mat gt_labels = ReadGroundTruthLabels(gt_path, &style);
  const bool scale = options.scale_result_to_gt && gt_labels.size() != result_labels.size() &&
                     SameShape(gt_labels.size(), result_labels.size());
  if (scale) {
    cv::Mat scaled;
    cv::resize(result_labels, scaled, gt_labels.size(), 0, 0, cv::INTER_NEAREST);
    result_labels = scaled;
  }
  cv::Point offset;
  const bool crop = gt_labels.size() != result_labels.size() || options.gt_offset.has_value();
  if (crop) {
    offset = options.gt_offset ? *options.gt_offset
                               : FindGroundTruthOffset(gt_labels, result_labels).offset;
    gt_labels = CropGroundTruth(gt_labels, result_labels.size(), offset);
  }
  const ZoneOverlaps counts = CountZoneOverlaps(result_labels, gt_labels);
  MapEvaluation evaluation = ScoreZoneOverlaps(counts, options.mcc_variant);
  const std::string result_kinds = KindsPathFor(result_path), gt_kinds = KindsPathFor(gt_path);
  std::error_code error;
  if (std::filesystem::is_regular_file(result_kinds, error) &&
      std::filesystem::is_regular_file(gt_kinds, error)) {
    evaluation.kind_accuracy =
        KindAccuracy(counts, ReadZoneKinds(result_kinds), ReadZoneKinds(gt_kinds));
  }
  evaluation.name = std::filesystem::path(result_path).stem().string();
  evaluation.result_path = result_path;
  evaluation.gt_path = gt_path;
  evaluation.gt_style = style;
  evaluation.gt_cropped = crop;
  evaluation.gt_offset = offset;
  evaluation.result_scaled = scale;
  return evaluation;
}

}  // namespace areagraph

#pragma once

#include <cstdint>
#include <opencv2/core.hpp>
#include <optional>
#include <string>

#include "tools/eval/ground_truth.h"
#include "tools/eval/per_zone_mcc.h"
#include "tools/eval/segmentation_reader.h"
#include "tools/eval/zone_overlaps.h"

namespace areagraph {

// Everything that decides how one segmentation is scored.
struct EvaluationOptions {
  // kAuto guesses per file (DetectGroundTruthStyle).
  GroundTruthStyle gt_style = GroundTruthStyle::kAuto;
  MccVariant mcc_variant = MccVariant::kStandard;
  SegmentationReading reading = SegmentationReading::kAuto;
  // Where the segmentation lies in a bigger GT; unset = search for it.
  std::optional<cv::Point> gt_offset;
  // Result segments of at most this many pixels are dropped before scoring
  // (0 keeps all).
  int drop_result_segments_px = 0;
  // A segmentation of another size than its GT but of the same shape (aspect
  // ratios within 1 %) is scaled to the GT's size (nearest neighbour) instead
  // of being looked for inside it: for maps published downscaled, such as
  // bormann/lab_b_scan_furnitures_trashbins.
  bool scale_result_to_gt = false;
};

// The scores of one segmentation against its ground truth.
struct MapEvaluation {
  std::string name;
  std::string result_path;
  std::string gt_path;
  GroundTruthStyle gt_style = GroundTruthStyle::kAuto;
  // Whether the GT was cropped to the segmentation, and where: the
  // segmentation's top-left pixel in the GT.
  bool gt_cropped = false;
  cv::Point gt_offset;
  // Whether the segmentation was scaled to the GT's size.
  bool result_scaled = false;
  double mcc = 0;
  double precision = 0;
  double recall = 0;
  // Distinct labels > 0 in the segmentation and in the GT (after the GT
  // style's own filtering).
  int result_segments = 0;
  int gt_segments = 0;
  // Pixels inside a segment in both images (the MCC's N).
  int64_t scored_pixels = 0;
  // KindAccuracy (zone_kinds.h), when both images have a kinds file.
  std::optional<double> kind_accuracy;
};

// Scores two label images of the same size (CV_32S).
MapEvaluation ScoreLabelImages(const cv::Mat& result_labels, const cv::Mat& gt_labels,
                               MccVariant variant);

// The same from the two images' overlap counts.
MapEvaluation ScoreZoneOverlaps(const ZoneOverlaps& counts, MccVariant variant);

// The segments of a ground-truth file (CV_32S labels, 0 = none), read the way
// the scoring reads them; `style` kAuto is replaced by the detected style.
cv::Mat ReadGroundTruthLabels(const std::string& path, GroundTruthStyle* style);

// Reads, labels, aligns and scores one segmentation file against one GT file,
// and the kinds of their zones when both have a kinds file (KindsPathFor).
// Throws InputError for unreadable files and sizes that cannot be aligned.
MapEvaluation EvaluateMap(const std::string& result_path, const std::string& gt_path,
                          const EvaluationOptions& options);

}  // namespace areagraph

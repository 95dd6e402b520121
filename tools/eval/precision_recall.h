#pragma once

#include "tools/eval/zone_overlaps.h"

namespace areagraph {

struct PrecisionRecall {
  double precision = 0;
  double recall = 0;
  // Segments of more than 100 px that entered the averages.
  int result_segments = 0;
  int gt_segments = 0;
};

// Bormann's per-room precision and recall (EvaluationSegmentation::
// computePrecisionRecall, the averages of individual values it calls
// "micro"). Only segments of more than 100 px count, in both images.
// Precision = mean over result segments of (largest overlap with one GT
// segment) / (result segment size); recall = mean over GT segments of (largest
// overlap with one result segment) / (GT segment size). Sizes are over the
// whole image. An empty side gives 0.
PrecisionRecall ComputePrecisionRecall(const ZoneOverlaps& counts);

}  // namespace areagraph

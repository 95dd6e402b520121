#pragma once

#include <opencv2/core.hpp>
#include <string>

namespace areagraph {

// How a ground-truth image encodes its segments.
enum class GroundTruthStyle {
  kAuto,
  // Each chromatic colour is one segment; white, black and greys are
  // background (the Area Graph dataset's GT/). Colours of <= 100 px dropped.
  kColour,
  // Bormann's line style: the map with room borders drawn across doorways.
  // Rooms = 8-connected components of grey > 250; components <= 100 px dropped
  // (EvaluationSegmentation::computePrecisionRecall).
  kLines,
  // The same images read the way MAORIS' segment_Ground_Truth does: grey > 250,
  // one 3x3 erosion, top-level contours (RETR_CCOMP) filled, one 3x3 dilation.
  kMaorisLines,
  // A label image: every grey value > 0 is one segment, nothing dropped.
  kLabels,
};

// "auto", "colour", "lines", "maoris-lines", "labels" (also "color").
GroundTruthStyle ParseGroundTruthStyle(const std::string& name);
std::string GroundTruthStyleName(GroundTruthStyle style);

// Guesses the style of a raw image (as ReadImageFile returns it): colour when
// more than 100 pixels are chromatic; otherwise lines when at least 5 % of the
// pixels are brighter than 250 (free space), else labels. 16-bit grey images
// are always labels.
GroundTruthStyle DetectGroundTruthStyle(const cv::Mat& raw);

// Segments of a ground truth of style `style` (not kAuto). `raw` is the image
// as stored and `grey` the same file read as 8-bit grey (for the line styles).
cv::Mat GroundTruthLabels(const cv::Mat& raw, const cv::Mat& grey, GroundTruthStyle style);

// Segments at most this big (in pixels) are dropped from colour and line GT,
// as Bormann's evaluation does.
inline constexpr int kSmallSegmentPixels = 100;

// Bormann's rooms: 8-connected components of `grey` > 250, small ones dropped.
cv::Mat LabelsFromLines(const cv::Mat& grey);

// MAORIS' segment_Ground_Truth on `grey` (labels saturate at 255 like its
// 8-bit image).
cv::Mat LabelsFromLinesLikeMaoris(const cv::Mat& grey);

}  // namespace areagraph

#include "tools/eval/segmentation_reader.h"

#include <opencv2/imgcodecs.hpp>

#include "tools/eval/label_image.h"

namespace areagraph {

cv::Mat ReadSegmentationLabels(const std::string& path, SegmentationReading reading) {
  const cv::Mat raw = ReadImageFile(path);
  if (reading == SegmentationReading::kGreyLikeMaoris) {
    // The exact call MAORIS makes, so that colours merge as they did there.
    return LabelsFromGreyValues(ReadImageFile(path, cv::IMREAD_GRAYSCALE));
  }
  if (raw.channels() >= 3 && CountChromaticPixels(raw) > 0) return LabelsFromColours(raw);
  return LabelsFromGreyValues(raw);
}

}  // namespace areagraph

#pragma once

#include <opencv2/core.hpp>
#include <vector>

#include "stages/geometry/region_boxes.h"

namespace areagraph {

// Breadth-first growth of every non-zero label of `labels` (CV_32S) into the
// zero cells where `domain` (CV_8U, the same size) is non-zero, 4-connected,
// seeded in row-major order: each such cell takes the label that reaches it
// first (ties to the earlier seed).
void GrowLabels(const cv::Mat& domain, cv::Mat* labels);

// GrowLabels, where a growth has left no labelled cell beside an open one
// and the runs `cleared` (of domain cells) were unlabelled since: the seeds
// are then the labelled cells beside a cleared cell, and only those cells
// are looked at instead of the whole map.
void GrowIntoCleared(const std::vector<PieceRun>& cleared, const cv::Mat& domain, cv::Mat* labels);

}  // namespace areagraph

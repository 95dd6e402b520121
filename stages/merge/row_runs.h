#pragma once

#include <cstdint>
#include <opencv2/core.hpp>
#include <vector>

#include "stages/geometry/region_boxes.h"

namespace areagraph {

// The end of the run of cells equal to row[begin] (begin < cols): the first
// column after `begin` that differs, or cols. Compares 4 labels or 16 bytes
// at a time where SSE2 is: merge's rasters are mostly long runs.
int RunEnd(const int* row, int begin, int cols);
int RunEnd(const uint8_t* row, int begin, int cols);

// RunPieces (stages/geometry/region_boxes.h) with the runs found by RunEnd:
// the same runs, pieces and numbering.
int PiecesOverRuns(const cv::Mat& cells, std::vector<PieceRun>* runs,
                   std::vector<int>* piece_of_run);

}  // namespace areagraph

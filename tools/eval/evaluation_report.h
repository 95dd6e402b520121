#pragma once

#include <string>

#include "tools/eval/dataset_evaluation.h"
#include "tools/eval/map_evaluation.h"

namespace areagraph {

// "MCC 0.912\nprecision 0.870\nrecall 0.905\nsegments 12/10\n" plus the GT
// style and, when the GT was cropped, its offset.
std::string FormatMapText(const MapEvaluation& map);

// A Markdown table with one row per map (map, MCC, precision, recall,
// segments found/GT) and rows for the mean and median.
std::string FormatDatasetMarkdown(const DatasetEvaluation& dataset);

// The same as JSON objects (protobuf's JSON printer of a Struct).
std::string FormatMapJson(const MapEvaluation& map);
std::string FormatDatasetJson(const DatasetEvaluation& dataset);

}  // namespace areagraph

#pragma once

#include <string>
#include <vector>

#include "tools/eval/map_evaluation.h"

namespace areagraph {

// How result files are paired with GT files: the result "<key><suffix>.<ext>"
// goes with the GT "<key><gt_suffix>.png" (or ".<ext>").
struct DatasetLayout {
  std::string results_dir;
  std::string gt_dir;
  std::string suffix;
  std::string gt_suffix;
};

// One result file and the GT file it is scored against.
struct DatasetEntry {
  std::string result_path;
  std::string gt_path;
};

// The image files of `results_dir` (sorted by name) whose stem ends in
// `suffix` and that have a GT file; files without a GT are skipped. Throws
// InputError when a folder is missing or nothing pairs up.
std::vector<DatasetEntry> PairDatasetFiles(const DatasetLayout& layout);

// A scored dataset: one row per map that scored, plus one line per failure.
struct DatasetEvaluation {
  std::vector<MapEvaluation> maps;
  std::vector<std::string> failures;
};

DatasetEvaluation EvaluateDataset(const DatasetLayout& layout, const EvaluationOptions& options);

// Mean and median of a list of values (0 for an empty list).
double Mean(const std::vector<double>& values);
double Median(std::vector<double> values);

}  // namespace areagraph

#include "tools/eval/dataset_evaluation.h"

#include <algorithm>
#include <filesystem>
#include <numeric>
#include <set>

#include "common/error.h"

namespace areagraph {

namespace fs = std::filesystem;

namespace {

bool IsImageFile(const fs::path& path) {
  static const std::set<std::string> kExtensions = {".png", ".pgm",  ".ppm", ".bmp",
                                                    ".tif", ".tiff", ".jpg", ".jpeg"};
  std::string extension = path.extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return kExtensions.count(extension) > 0;
}

bool EndsWith(const std::string& text, const std::string& suffix) {
  return text.size() >= suffix.size() &&
         text.compare(text.size() - suffix.size(), suffix.size(), suffix) == 0;
}

void RequireFolder(const std::string& path, const std::string& what) {
  std::error_code error;
  if (!fs::is_directory(path, error)) {
    throw InputError(what + " folder '" + path + "' does not exist");
  }
}

}  // namespace

std::vector<DatasetEntry> PairDatasetFiles(const DatasetLayout& layout) {
  RequireFolder(layout.results_dir, "results");
  RequireFolder(layout.gt_dir, "ground-truth");
  std::vector<fs::path> results;
  for (const fs::directory_entry& entry : fs::directory_iterator(layout.results_dir)) {
    if (entry.is_regular_file() && IsImageFile(entry.path())) results.push_back(entry.path());
  }
  std::sort(results.begin(), results.end());
  std::vector<DatasetEntry> pairs;
  for (const fs::path& result : results) {
    const std::string stem = result.stem().string();
    if (!EndsWith(stem, layout.suffix)) continue;
    const std::string key = stem.substr(0, stem.size() - layout.suffix.size());
    for (const std::string& extension : {std::string(".png"), result.extension().string()}) {
      const fs::path gt = fs::path(layout.gt_dir) / (key + layout.gt_suffix + extension);
      std::error_code error;
      if (fs::is_regular_file(gt, error)) {
        pairs.push_back({result.string(), gt.string()});
        break;
      }
    }
  }
  if (pairs.empty()) {
    throw InputError("no file in '" + layout.results_dir + "' has a ground truth in '" +
                     layout.gt_dir + "' (check --suffix and --gt-suffix)");
  }
  return pairs;
}

DatasetEvaluation EvaluateDataset(const DatasetLayout& layout, const EvaluationOptions& options) {
  DatasetEvaluation dataset;
  for (const DatasetEntry& entry : PairDatasetFiles(layout)) {
    try {
      MapEvaluation map = EvaluateMap(entry.result_path, entry.gt_path, options);
      // The map's name is the shared key, without the result suffix.
      map.name = map.name.substr(0, map.name.size() - layout.suffix.size());
      dataset.maps.push_back(std::move(map));
    } catch (const Error& error) {
      dataset.failures.push_back(fs::path(entry.result_path).filename().string() + ": " +
                                 error.what());
    }
  }
  return dataset;
}

double Mean(const std::vector<double>& values) {
  if (values.empty()) return 0;
  return std::accumulate(values.begin(), values.end(), 0.0) / static_cast<double>(values.size());
}

double Median(std::vector<double> values) {
  if (values.empty()) return 0;
  std::sort(values.begin(), values.end());
  const size_t middle = values.size() / 2;
  return values.size() % 2 == 1 ? values[middle] : (values[middle - 1] + values[middle]) / 2;
}

}  // namespace areagraph

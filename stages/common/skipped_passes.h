#pragma once

#include <algorithm>

namespace areagraph {

// Whether a stage's `options` run `pass`: it is not in their skip_passes,
// the list every stage with passes beyond the paper has (CleanOptions,
// CutOptions, MergeOptions, MatchOptions).
template <typename StageOptions>
bool RunsStagePass(const StageOptions& options, typename StageOptions::Pass pass) {
  const auto& skipped = options.skip_passes();
  return std::find(skipped.begin(), skipped.end(), pass) == skipped.end();
}

}  // namespace areagraph

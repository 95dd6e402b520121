#include "stages/import/grid_map_decoder.h"

#include <vector>
#ifdef __SSE2__
#include <immintrin.h>
#endif

#include "common/error.h"
#include "stages/common/pipeline_options_check.h"

namespace areagraph {

GreyToCell GreyThresholdRule(const proto::ImportOptions& options) {
  CheckImportOptions(options);
  const int occupied_max = options.occupied_max_grey();
  const int free_min = options.free_min_grey();
  GreyToCell rule;
  for (int grey = 0; grey < 256; ++grey) {
    rule[grey] = grey >= free_min       ? proto::CELL_FREE
                 : grey <= occupied_max ? proto::CELL_OCCUPIED
                                        : proto::CELL_UNKNOWN;
  }
  return rule;
}

GreyToCell MapServerRule(const MapYaml& yaml) {
  GreyToCell rule;
  for (int grey = 0; grey < 256; ++grey) {
    const int value = yaml.negate ? 255 - grey : grey;
    if (yaml.mode == MapYaml::Mode::kRaw && value > 100) {
      rule[grey] = proto::CELL_UNKNOWN;
      continue;
    }
    const double occupancy =
        yaml.mode == MapYaml::Mode::kRaw ? value / 100.0 : (255 - value) / 255.0;
    rule[grey] = occupancy > yaml.occupied_thresh ? proto::CELL_OCCUPIED
                 : occupancy < yaml.free_thresh   ? proto::CELL_FREE
                                                  : proto::CELL_UNKNOWN;
  }
  return rule;
}

#ifdef __SSE2__
namespace {

// Where the byte rule changes value: the greys g > 0 with rule[g] != rule[g - 1].
std::vector<int> RuleSteps(const uint8_t* rule) {
  std::vector<int> steps;
  for (int grey = 1; grey < 256; ++grey) {
    if (rule[grey] != rule[grey - 1]) steps.push_back(grey);
  }
  return steps;
}

}  // namespace
#endif

std::string ClassifyCells(const cv::Mat& grey, const GreyToCell& rule) {
  CV_Assert(grey.type() == CV_8UC1);
  // A byte table and local pointers: the enum table is 4 bytes an entry, and
  // stores through the string's chars may alias anything, so indexing the
  // string reloaded its buffer per cell.
  uint8_t byte_rule[256];
  for (int grey_value = 0; grey_value < 256; ++grey_value) {
    byte_rule[grey_value] = static_cast<uint8_t>(rule[grey_value]);
  }
  std::string cells(static_cast<size_t>(grey.rows) * grey.cols, '\0');
  auto* out = reinterpret_cast<uint8_t*>(cells.data());
#ifdef __SSE2__
  // Every rule here is a few steps (free, unknown, occupied by thresholds):
  // rule[0] plus, for each step g at or below the grey, the change there
  // (bytes wrap, so any values add up), sixteen pixels at a time.
  const std::vector<int> steps = RuleSteps(byte_rule);
  constexpr size_t kMostSteps = 4;
  __m128i at[kMostSteps], change[kMostSteps];
  const bool few = steps.size() <= kMostSteps;
  for (size_t i = 0; few && i < steps.size(); ++i) {
    at[i] = _mm_set1_epi8(static_cast<char>(steps[i]));
    change[i] = _mm_set1_epi8(static_cast<char>(byte_rule[steps[i]] - byte_rule[steps[i] - 1]));
  }
  const __m128i first = _mm_set1_epi8(static_cast<char>(byte_rule[0]));
#endif
  for (int row = 0; row < grey.rows; ++row) {
    const uint8_t* pixels = grey.ptr<uint8_t>(row);
    int col = 0;
#ifdef __SSE2__
    for (; few && col + 16 <= grey.cols; col += 16) {
      const __m128i g = _mm_loadu_si128(reinterpret_cast<const __m128i*>(pixels + col));
      __m128i value = first;
      for (size_t i = 0; i < steps.size(); ++i) {
        // g >= step: max(g, step) == g, unsigned.
        const __m128i reached = _mm_cmpeq_epi8(_mm_max_epu8(g, at[i]), g);
        value = _mm_add_epi8(value, _mm_and_si128(reached, change[i]));
      }
      _mm_storeu_si128(reinterpret_cast<__m128i*>(out + col), value);
    }
#endif
    for (; col < grey.cols; ++col) out[col] = byte_rule[pixels[col]];
    out += grey.cols;
  }
  return cells;
}

}  // namespace areagraph

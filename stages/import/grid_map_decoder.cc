#include "stages/import/grid_map_decoder.h"

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
  for (int row = 0; row < grey.rows; ++row) {
    const uint8_t* pixels = grey.ptr<uint8_t>(row);
    for (int col = 0; col < grey.cols; ++col) out[col] = byte_rule[pixels[col]];
    out += grey.cols;
  }
  return cells;
}

}  // namespace areagraph

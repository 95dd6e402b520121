#pragma once

#include <string>

namespace areagraph {

// A ROS map_server map description (the YAML beside the image).
struct MapYaml {
  enum class Mode { kTrinary, kScale, kRaw };

  // `image` as written in the YAML, and resolved against the YAML's folder.
  std::string image;
  std::string image_path;
  double resolution_m = 0;
  double origin_x_m = 0;
  double origin_y_m = 0;
  double origin_yaw_rad = 0;
  bool negate = false;
  double occupied_thresh = 0.65;
  double free_thresh = 0.196;
  Mode mode = Mode::kTrinary;
};

// Parses map_server YAML text read from `yaml_path`. `resolution` is required;
// `image` too when `image_required`. `origin` ([x, y] or [x, y, yaw]),
// `negate` (0/1 or true/false), `occupied_thresh`, `free_thresh` and `mode`
// (trinary, scale or raw) take map_server's defaults when absent. Throws
// InputError with one line naming the file and the offending key.
MapYaml ParseMapYaml(const std::string& yaml_text, const std::string& yaml_path,
                     bool image_required);

}  // namespace areagraph

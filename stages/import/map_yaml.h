#pragma once

#include <string>

namespace areagraph {

// Largest accepted distance of a map origin from the world origin. UTM
// northings reach 1e7 m; far beyond that, doubles lose the centimetres of
// the map's cells and exports (GeoJSON, osmAG) come out degenerate.
inline constexpr double kMaxOriginM = 1e8;

// "" when (x, y, yaw) is a usable map origin: finite, |x| and |y| at most
// kMaxOriginM, |yaw| at most 2 pi. Otherwise what is wrong with it.
std::string OriginProblem(double x_m, double y_m, double yaw_rad);

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
// `image` too when `image_required`. `origin` ([x, y, yaw], as map_server
// requires), `negate` (0/1 or true/false), `occupied_thresh`, `free_thresh`
// and `mode` (trinary, scale or raw) take map_server's defaults when absent.
// A key given twice is refused (YAML forbids it; parsers differ on which
// wins). Throws InputError with one line naming the file and the offending key.
MapYaml ParseMapYaml(const std::string& yaml_text, const std::string& yaml_path,
                     bool image_required);

}  // namespace areagraph

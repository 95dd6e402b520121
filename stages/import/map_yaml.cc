#include "stages/import/map_yaml.h"

#include <yaml-cpp/yaml.h>

#include <cmath>
#include <filesystem>
#include <set>
#include <sstream>

#include "common/error.h"
#include "common/text.h"
#include "stages/common/pipeline_options_check.h"

namespace areagraph {
namespace {

// Wraps yaml-cpp's conversions so that every failure names file and key.
class YamlReader {
 public:
  YamlReader(const YAML::Node& root, const std::string& path) : root_(root), path_(path) {}

  [[noreturn]] void Fail(const std::string& message) const {
    throw InputError("map YAML '" + path_ + "': " + message);
  }

  bool Has(const char* key) const { return root_[key].IsDefined() && !root_[key].IsNull(); }

  // yaml-cpp keeps every pair of a mapping, so a repeated key is still there.
  void RefuseRepeatedKeys() const {
    std::set<std::string> seen;
    for (const auto& pair : root_) {
      const std::string key = pair.first.IsScalar() ? pair.first.Scalar() : "(not a name)";
      if (!seen.insert(key).second) Fail("'" + key + "' is given twice");
    }
  }

  double Number(const char* key) const { return Number(root_[key], key); }

  double Number(const YAML::Node& node, const std::string& key) const {
    double value = 0;
    if (!node.IsScalar() || !YAML::convert<double>::decode(node, value)) {
      Fail("'" + key + "' must be a number");
    }
    if (!std::isfinite(value)) Fail("'" + key + "' must be finite, got " + node.Scalar());
    return value;
  }

  std::string String(const char* key) const {
    const YAML::Node node = root_[key];
    if (!node.IsScalar() || node.Scalar().empty()) Fail(std::string("'") + key + "' must be text");
    // "map.png\0.txt" would open map.png: the file system ends a name at NUL.
    if (node.Scalar().find('\0') != std::string::npos) {
      Fail(std::string("'") + key + "' holds a NUL byte");
    }
    return node.Scalar();
  }

  bool Flag(const char* key) const {
    const YAML::Node node = root_[key];
    bool flag = false;
    int number = 0;
    if (node.IsScalar() && YAML::convert<int>::decode(node, number) &&
        (number == 0 || number == 1)) {
      return number == 1;
    }
    if (node.IsScalar() && YAML::convert<bool>::decode(node, flag)) return flag;
    Fail(std::string("'") + key + "' must be 0 or 1");
  }

  double Probability(const char* key) const {
    const double value = Number(key);
    if (value < 0 || value > 1) {
      Fail(std::string("'") + key + "' must lie in [0, 1], got " + FormatNumber(value));
    }
    return value;
  }

 private:
  YAML::Node root_;
  std::string path_;
};

YAML::Node LoadYaml(const std::string& yaml_text, const std::string& yaml_path) {
  try {
    return YAML::Load(yaml_text);
  } catch (const YAML::Exception& e) {
    throw InputError("map YAML '" + yaml_path + "' is malformed: " + e.msg + " (line " +
                     std::to_string(e.mark.line + 1) + ")");
  }
}

}  // namespace

std::string OriginProblem(double x_m, double y_m, double yaw_rad) {
  constexpr double kTwoPi = 6.283185307179586;
  if (!(std::fabs(x_m) <= kMaxOriginM) || !(std::fabs(y_m) <= kMaxOriginM)) {  // NaN fails
    return "origin x and y must be finite metres within +-" + FormatNumber(kMaxOriginM) + ", got " +
           FormatNumber(x_m) + ", " + FormatNumber(y_m);
  }
  if (!(std::fabs(yaw_rad) <= kTwoPi)) {
    return "origin yaw must be finite radians within +-2 pi, got " + FormatNumber(yaw_rad);
  }
  return "";
}

MapYaml ParseMapYaml(const std::string& yaml_text, const std::string& yaml_path,
                     bool image_required) {
  const YAML::Node root = LoadYaml(yaml_text, yaml_path);
  const YamlReader reader(root, yaml_path);
  if (!root.IsMap()) reader.Fail("expected keys such as 'image' and 'resolution'");
  reader.RefuseRepeatedKeys();

  MapYaml yaml;
  if (reader.Has("image")) {
    yaml.image = reader.String("image");
    const std::filesystem::path folder = std::filesystem::path(yaml_path).parent_path();
    yaml.image_path = (folder / yaml.image).lexically_normal().string();
    if (std::filesystem::path(yaml.image).is_absolute()) yaml.image_path = yaml.image;
  } else if (image_required) {
    reader.Fail("lacks 'image'");
  }

  if (!reader.Has("resolution")) reader.Fail("lacks 'resolution'");
  yaml.resolution_m = reader.Number("resolution");
  try {
    CheckResolution(yaml.resolution_m, "'resolution'", /*is_option=*/false);
  } catch (const InputError& e) {
    reader.Fail(e.what());
  }

  if (reader.Has("origin")) {
    const YAML::Node origin = root["origin"];
    if (!origin.IsSequence() || origin.size() != 3) {
      reader.Fail("'origin' must be [x, y, yaw] (three numbers, as map_server reads it)");
    }
    yaml.origin_x_m = reader.Number(origin[0], "origin x");
    yaml.origin_y_m = reader.Number(origin[1], "origin y");
    yaml.origin_yaw_rad = reader.Number(origin[2], "origin yaw");
    const std::string problem =
        OriginProblem(yaml.origin_x_m, yaml.origin_y_m, yaml.origin_yaw_rad);
    if (!problem.empty()) reader.Fail("'origin': " + problem);
  }
  if (reader.Has("negate")) yaml.negate = reader.Flag("negate");
  if (reader.Has("occupied_thresh")) yaml.occupied_thresh = reader.Probability("occupied_thresh");
  if (reader.Has("free_thresh")) yaml.free_thresh = reader.Probability("free_thresh");
  if (yaml.free_thresh > yaml.occupied_thresh) {
    reader.Fail("'free_thresh' (" + FormatNumber(yaml.free_thresh) +
                ") must not exceed 'occupied_thresh' (" + FormatNumber(yaml.occupied_thresh) + ")");
  }
  if (reader.Has("mode")) {
    const std::string mode = reader.String("mode");
    if (mode == "trinary") {
      yaml.mode = MapYaml::Mode::kTrinary;
    } else if (mode == "scale") {
      yaml.mode = MapYaml::Mode::kScale;
    } else if (mode == "raw") {
      yaml.mode = MapYaml::Mode::kRaw;
    } else {
      reader.Fail("'mode' must be trinary, scale or raw, got '" + mode + "'");
    }
  }
  return yaml;
}

}  // namespace areagraph

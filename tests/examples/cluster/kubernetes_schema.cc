#include "tests/examples/cluster/kubernetes_schema.h"

#include <algorithm>
#include <map>
#include <regex>

namespace areagraph::testing {
namespace {

// What a field holds: a scalar type, an object of a named type, a list of
// those, or a map of strings (labels, resource quantities).
enum class Kind { kString, kInt, kBool, kObject, kList, kStringMap };

struct Field {
  Kind kind;
  std::string type;  // object type for kObject and kList ("" = strings)
  bool required = false;
  std::vector<std::string> values;  // allowed values of an enum string
};

using Schema = std::map<std::string, std::map<std::string, Field>>;

// Short names for the table below.
Field Text(bool required = false, std::vector<std::string> values = {}) {
  return {Kind::kString, "", required, std::move(values)};
}
Field Number() { return {Kind::kInt, "", false, {}}; }
Field Flag() { return {Kind::kBool, "", false, {}}; }
Field Of(const std::string& type, bool required = false) {
  return {Kind::kObject, type, required, {}};
}
Field ListOf(const std::string& type, bool required = false) {
  return {Kind::kList, type, required, {}};
}
Field StringMap() { return {Kind::kStringMap, "", false, {}}; }

// The subset of batch/v1 and core/v1 that the examples use.
const Schema& KubernetesSchema() {
  static const Schema schema = {
      {"Job",
       {{"apiVersion", Text(true, {"batch/v1"})},
        {"kind", Text(true, {"Job"})},
        {"metadata", Of("ObjectMeta", true)},
        {"spec", Of("JobSpec", true)}}},
      {"ObjectMeta",
       {{"name", Text(true)},
        {"namespace", Text()},
        {"labels", StringMap()},
        {"annotations", StringMap()}}},
      {"JobSpec",
       {{"completionMode", Text(false, {"NonIndexed", "Indexed"})},
        {"completions", Number()},
        {"parallelism", Number()},
        {"backoffLimit", Number()},
        {"activeDeadlineSeconds", Number()},
        {"ttlSecondsAfterFinished", Number()},
        {"template", Of("PodTemplateSpec", true)}}},
      {"PodTemplateSpec", {{"metadata", Of("ObjectMeta")}, {"spec", Of("PodSpec", true)}}},
      {"PodSpec",
       {{"restartPolicy", Text(false, {"Always", "OnFailure", "Never"})},
        {"containers", ListOf("Container", true)},
        {"volumes", ListOf("Volume")}}},
      {"Container",
       {{"name", Text(true)},
        {"image", Text(true)},
        {"command", ListOf("")},
        {"args", ListOf("")},
        {"workingDir", Text()},
        {"env", ListOf("EnvVar")},
        {"resources", Of("ResourceRequirements")},
        {"volumeMounts", ListOf("VolumeMount")}}},
      {"EnvVar", {{"name", Text(true)}, {"value", Text()}}},
      {"ResourceRequirements", {{"requests", StringMap()}, {"limits", StringMap()}}},
      {"VolumeMount",
       {{"name", Text(true)},
        {"mountPath", Text(true)},
        {"readOnly", Flag()},
        {"subPath", Text()}}},
      {"Volume",
       {{"name", Text(true)}, {"persistentVolumeClaim", Of("PersistentVolumeClaimVolumeSource")}}},
      {"PersistentVolumeClaimVolumeSource", {{"claimName", Text(true)}, {"readOnly", Flag()}}},
  };
  return schema;
}

// A plain scalar that YAML resolves to a number or boolean is not a string
// for the API server; quoted scalars (tag "!") always are.
bool IsNonString(const YAML::Node& node) {
  if (node.Tag() == "!") return false;
  static const std::regex number_or_bool(
      R"([-+]?(\d+|\d*\.\d+([eE][-+]?\d+)?|0x[0-9a-fA-F]+)|true|false|True|False|null|~)");
  return std::regex_match(node.Scalar(), number_or_bool);
}

class Checker {
 public:
  std::vector<std::string> problems;

  void Object(const YAML::Node& node, const std::string& type, const std::string& path) {
    if (!node.IsMap()) return Problem(path, "must be an object of type " + type);
    const auto& fields = KubernetesSchema().at(type);
    for (const auto& entry : node) {
      const std::string key = entry.first.as<std::string>();
      const auto field = fields.find(key);
      if (field == fields.end()) {
        Problem(path + "." + key, "is not a field of " + type);
      } else {
        Value(entry.second, field->second, path + "." + key);
      }
    }
    for (const auto& [key, field] : fields) {
      if (field.required && !node[key]) Problem(path + "." + key, "is required in " + type);
    }
  }

 private:
  void Problem(const std::string& path, const std::string& what) {
    problems.push_back(path + " " + what);
  }

  void Value(const YAML::Node& node, const Field& field, const std::string& path) {
    switch (field.kind) {
      case Kind::kString:
        if (!node.IsScalar() || IsNonString(node)) return Problem(path, "must be a string");
        if (!field.values.empty() && std::find(field.values.begin(), field.values.end(),
                                               node.Scalar()) == field.values.end()) {
          Problem(path, "has a value Kubernetes does not know: " + node.Scalar());
        }
        return;
      case Kind::kInt:
        if (!node.IsScalar() || node.Tag() == "!" ||
            !std::regex_match(node.Scalar(), std::regex(R"(\d+)"))) {
          Problem(path, "must be a non-negative integer");
        }
        return;
      case Kind::kBool:
        if (!node.IsScalar() || (node.Scalar() != "true" && node.Scalar() != "false")) {
          Problem(path, "must be true or false");
        }
        return;
      case Kind::kObject:
        return Object(node, field.type, path);
      case Kind::kStringMap:
        if (!node.IsMap()) return Problem(path, "must be a map");
        for (const auto& entry : node) {
          if (!entry.second.IsScalar()) Problem(path, "values must be scalars");
        }
        return;
      case Kind::kList:
        if (!node.IsSequence()) return Problem(path, "must be a list");
        for (size_t i = 0; i < node.size(); ++i) {
          const std::string item = path + "[" + std::to_string(i) + "]";
          if (field.type.empty()) {
            if (!node[i].IsScalar()) Problem(item, "must be a string");
          } else {
            Object(node[i], field.type, item);
          }
        }
        return;
    }
  }
};

}  // namespace

std::vector<std::string> CheckKubernetesJob(const YAML::Node& manifest) {
  Checker checker;
  checker.Object(manifest, "Job", "");
  if (!checker.problems.empty()) return checker.problems;
  // Rules of the Job API beyond field types.
  const YAML::Node spec = manifest["spec"];
  const std::string restart = spec["template"]["spec"]["restartPolicy"].as<std::string>("Always");
  if (restart != "Never" && restart != "OnFailure") {
    checker.problems.push_back(
        ".spec.template.spec.restartPolicy of a Job must be Never or "
        "OnFailure, not " +
        restart);
  }
  if (spec["completionMode"].as<std::string>("") == "Indexed" && !spec["completions"]) {
    checker.problems.push_back(".spec.completions is required for an Indexed Job");
  }
  static const std::regex dns_label("[a-z0-9]([-a-z0-9]*[a-z0-9])?");
  if (!std::regex_match(manifest["metadata"]["name"].as<std::string>(), dns_label)) {
    checker.problems.push_back(".metadata.name is not a DNS-1123 label");
  }
  // Every mount names a volume of the pod.
  const YAML::Node pod = spec["template"]["spec"];
  for (const auto& container : pod["containers"]) {
    for (const auto& mount : container["volumeMounts"]) {
      bool found = false;
      for (const auto& volume : pod["volumes"]) {
        found = found || volume["name"].as<std::string>() == mount["name"].as<std::string>();
      }
      if (!found) {
        checker.problems.push_back("volume mount " + mount["name"].as<std::string>() +
                                   " names no volume of the pod");
      }
    }
  }
  return checker.problems;
}

}  // namespace areagraph::testing

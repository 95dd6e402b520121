#pragma once

#include <yaml-cpp/yaml.h>

#include <string>
#include <vector>

namespace areagraph::testing {

// Checks a parsed manifest against the fields of the Kubernetes objects that
// examples/cluster uses (batch/v1 Job down to Container, Volume and EnvVar,
// as the Kubernetes API reference defines them): every key must be a field of
// its object, of the field's type; required fields must be there; enums take
// their listed values; env values must be strings (an unquoted 8 is refused by
// the API server). Returns one line per problem, with the path of the field.
// Fields the examples do not use are not listed, so they count as unknown.
std::vector<std::string> CheckKubernetesJob(const YAML::Node& manifest);

}  // namespace areagraph::testing

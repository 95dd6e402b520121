#pragma once

#include <google/protobuf/message.h>

#include <memory>
#include <string>

namespace areagraph {

// A new, empty message of the artifact type named `proto_type` (as stored in
// the artifacts table), or nullptr for a type this build does not know.
std::unique_ptr<google::protobuf::Message> NewArtifactMessage(const std::string& proto_type);

}  // namespace areagraph

#pragma once

#include <google/protobuf/message.h>

#include <string>

namespace areagraph {

// `message` as indented JSON through protobuf's printer, with the .proto
// field names; `with_defaults` also prints fields that hold their default.
// Throws Error when the printer fails.
std::string MessageToJson(const google::protobuf::Message& message, bool with_defaults = false);

}  // namespace areagraph

#include "common/json.h"

#include <google/protobuf/util/json_util.h>

#include "common/error.h"

namespace areagraph {

std::string MessageToJson(const google::protobuf::Message& message, bool with_defaults) {
  google::protobuf::util::JsonPrintOptions options;
  options.add_whitespace = true;
  options.preserve_proto_field_names = true;
  options.always_print_primitive_fields = with_defaults;
  std::string json;
  const auto status = google::protobuf::util::MessageToJsonString(message, &json, options);
  if (!status.ok()) {
    throw Error("cannot print " + message.GetTypeName() + " as JSON: " + status.ToString());
  }
  return json;
}

}  // namespace areagraph

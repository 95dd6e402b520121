#include "tools/export/json_text.h"

#include <google/protobuf/util/json_util.h>

#include <charconv>
#include <cmath>
#include <cstdio>

#include "common/error.h"

namespace areagraph {

std::string JsonString(const std::string& text) {
  std::string quoted = "\"";
  for (const char c : text) {
    switch (c) {
      case '"':
        quoted += "\\\"";
        break;
      case '\\':
        quoted += "\\\\";
        break;
      case '\n':
        quoted += "\\n";
        break;
      case '\t':
        quoted += "\\t";
        break;
      default:
        if (static_cast<unsigned char>(c) < 0x20) {
          char escaped[8];
          std::snprintf(escaped, sizeof(escaped), "\\u%04x", c);
          quoted += escaped;
        } else {
          quoted += c;
        }
    }
  }
  return quoted + "\"";
}

std::string JsonNumber(double value) {
  char text[32];
  const auto result = std::to_chars(text, text + sizeof(text), value);
  return std::string(text, result.ptr);
}

std::string JsonNumber(double value, int decimals) {
  const double scale = std::pow(10.0, decimals);
  const double rounded = std::round(value * scale) / scale;
  // A value too large to scale is printed as it is; -0 prints as 0.
  return JsonNumber(std::isfinite(rounded) ? rounded + 0.0 : value);
}

std::string MessageJson(const google::protobuf::Message& message) {
  google::protobuf::util::JsonPrintOptions options;
  options.preserve_proto_field_names = true;
  std::string json;
  if (!google::protobuf::util::MessageToJsonString(message, &json, options).ok()) {
    throw Error("cannot print " + message.GetTypeName() + " as JSON");
  }
  return json;
}

std::string JsonLines(const std::vector<std::string>& items) {
  std::string text = "[\n";
  for (size_t i = 0; i < items.size(); ++i) {
    text += items[i] + (i + 1 < items.size() ? ",\n" : "\n");
  }
  return text + "]";
}

}  // namespace areagraph

#pragma once

#include <google/protobuf/message.h>

#include <string>
#include <vector>

namespace areagraph {

// Small pieces of JSON text for the GeoJSON and node-link writers, whose key
// order is fixed.

// `text` as a JSON string literal, quotes included.
std::string JsonString(const std::string& text);

// `message` as compact protobuf JSON (field names as in the .proto).
std::string MessageJson(const google::protobuf::Message& message);

// JSON values (already text) as an array, one per line.
std::string JsonLines(const std::vector<std::string>& items);

// The shortest decimal text that reads back as `value` (finite values only).
std::string JsonNumber(double value);

}  // namespace areagraph

#pragma once

#include <string>

namespace areagraph {

// Small pieces of JSON text for the GeoJSON writer, whose key order is fixed.

// `text` as a JSON string literal, quotes included.
std::string JsonString(const std::string& text);

// The shortest decimal text that reads back as `value` (finite values only).
std::string JsonNumber(double value);

}  // namespace areagraph

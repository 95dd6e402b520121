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

// How finely GeoJSON and JSON write positions: metres to the millimetre,
// degrees to 8 decimals (about a millimetre), so that no float noise
// (16.650000000000002) reaches a file. (osmAG writes OSM's 7, osm_xml.h.)
constexpr int kMetreDecimals = 3;
constexpr int kDegreeDecimals = 8;

// `value` rounded to `decimals` places, as the shortest text that reads back
// as that rounded value: 16.650000000000002 -> "16.65", 2.0 -> "2".
std::string JsonNumber(double value, int decimals);

}  // namespace areagraph

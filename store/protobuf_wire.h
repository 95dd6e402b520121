#pragma once

#include <string_view>

namespace areagraph {

// True when `bytes` is a sequence of well-formed protobuf fields (valid tags,
// varints and lengths, balanced groups). The store checks payloads with it
// without knowing their message types; nested messages are not descended into,
// since a length-delimited field may as well be a string.
bool IsWellFormedProtobuf(std::string_view bytes);

}  // namespace areagraph

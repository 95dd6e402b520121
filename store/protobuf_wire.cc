#include "store/protobuf_wire.h"

#include <cstdint>
#include <vector>

namespace areagraph {
namespace {

// Reads a base-128 varint of at most 10 bytes at `pos`; false when cut short.
bool ReadVarint(std::string_view bytes, size_t& pos, uint64_t& value) {
  value = 0;
  for (int shift = 0; shift < 64; shift += 7) {
    if (pos >= bytes.size()) return false;
    const auto byte = static_cast<uint8_t>(bytes[pos++]);
    value |= static_cast<uint64_t>(byte & 0x7f) << shift;
    if ((byte & 0x80) == 0) return true;
  }
  return false;
}

bool Skip(std::string_view bytes, size_t& pos, uint64_t count) {
  if (count > bytes.size() - pos) return false;
  pos += count;
  return true;
}

}  // namespace

bool IsWellFormedProtobuf(std::string_view bytes) {
  constexpr uint64_t kMaxFieldNumber = (1u << 29) - 1;
  std::vector<uint64_t> open_groups;
  size_t pos = 0;
  while (pos < bytes.size()) {
    uint64_t tag = 0, value = 0;
    if (!ReadVarint(bytes, pos, tag)) return false;
    const uint64_t field = tag >> 3;
    if (field == 0 || field > kMaxFieldNumber) return false;
    switch (tag & 7) {
      case 0:  // varint
        if (!ReadVarint(bytes, pos, value)) return false;
        break;
      case 1:  // fixed64
        if (!Skip(bytes, pos, 8)) return false;
        break;
      case 2:  // length-delimited
        if (!ReadVarint(bytes, pos, value) || !Skip(bytes, pos, value)) return false;
        break;
      case 3:  // start group
        open_groups.push_back(field);
        break;
      case 4:  // end group
        if (open_groups.empty() || open_groups.back() != field) return false;
        open_groups.pop_back();
        break;
      case 5:  // fixed32
        if (!Skip(bytes, pos, 4)) return false;
        break;
      default:
        return false;
    }
  }
  return open_groups.empty();
}

}  // namespace areagraph

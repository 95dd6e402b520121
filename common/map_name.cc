#include "common/map_name.h"

#include <algorithm>
#include <cstdio>

#include "common/error.h"

namespace areagraph {
namespace {

constexpr size_t kMaxMapNameBytes = 256;

// The length of the UTF-8 sequence at `i` (1 to 4), or 0 when it is not
// well-formed (overlong forms and surrogates included).
size_t Utf8SequenceLength(const std::string& text, size_t i) {
  const auto byte = [&](size_t k) { return static_cast<unsigned char>(text[k]); };
  const unsigned char first = byte(i);
  if (first < 0x80) return 1;
  size_t length = 0;
  unsigned char low = 0x80, high = 0xBF;
  if (first >= 0xC2 && first <= 0xDF) {
    length = 2;
  } else if (first >= 0xE0 && first <= 0xEF) {
    length = 3;
    if (first == 0xE0) low = 0xA0;
    if (first == 0xED) high = 0x9F;
  } else if (first >= 0xF0 && first <= 0xF4) {
    length = 4;
    if (first == 0xF0) low = 0x90;
    if (first == 0xF4) high = 0x8F;
  } else {
    return 0;
  }
  if (i + length > text.size()) return 0;
  if (byte(i + 1) < low || byte(i + 1) > high) return 0;
  for (size_t k = 2; k < length; ++k) {
    if (byte(i + k) < 0x80 || byte(i + k) > 0xBF) return 0;
  }
  return length;
}

// The name as it can be shown on one line: control bytes as \xNN.
std::string Shown(const std::string& name) {
  std::string shown;
  for (const char c : name) {
    const auto byte = static_cast<unsigned char>(c);
    if (byte < 0x20 || byte == 0x7f) {
      char escaped[8];
      std::snprintf(escaped, sizeof(escaped), "\\x%02x", byte);
      shown += escaped;
    } else {
      shown += c;
    }
  }
  return shown;
}

}  // namespace

void CheckMapName(const std::string& name) {
  const auto fail = [&](const std::string& what) {
    return InputError("map name '" + Shown(name) + "' " + what);
  };
  if (name.empty()) throw InputError("map name is empty");
  if (name.size() > kMaxMapNameBytes) {
    throw InputError("map name has " + std::to_string(name.size()) + " bytes; at most " +
                     std::to_string(kMaxMapNameBytes) + " are allowed");
  }
  for (size_t i = 0; i < name.size();) {
    const auto byte = static_cast<unsigned char>(name[i]);
    if (byte == ' ') throw fail("holds a blank");
    if (byte < 0x20 || byte == 0x7f) throw fail("holds a control character (a tab or line break)");
    const size_t length = Utf8SequenceLength(name, i);
    if (length == 0) throw fail("is not UTF-8 text");
    if (length == 2 && byte == 0xC2 && static_cast<unsigned char>(name[i + 1]) == 0xA0) {
      throw fail("holds a blank");  // U+00A0, the no-break space
    }
    i += length;
  }
  if (name.front() == '/' || name.back() == '/') throw fail("may not start or end with '/'");
  size_t start = 0;
  while (start <= name.size()) {
    const size_t end = std::min(name.find('/', start), name.size());
    const std::string part = name.substr(start, end - start);
    if (part.empty()) throw fail("holds an empty part ('//')");
    if (part == "." || part == "..") throw fail("may not hold a '" + part + "' part");
    start = end + 1;
  }
}

}  // namespace areagraph

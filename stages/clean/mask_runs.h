#pragma once

#include <cstdint>
#include <cstring>

namespace areagraph {

// Calls run(begin, end) for each run [begin, end) of non-zero bytes of
// row[0, n), a row of a 0 / 255 mask. Eight bytes at a time across long
// stretches of one value: a map is mostly such stretches.
template <typename Run>
void ForEachMaskRun(const uint8_t* row, int n, Run run) {
  auto eight = [&](int c) {
    uint64_t word;
    std::memcpy(&word, row + c, sizeof(word));
    return word;
  };
  int c = 0;
  while (c < n) {
    while (c + 8 <= n && eight(c) == 0) c += 8;
    while (c < n && row[c] == 0) ++c;
    if (c == n) return;
    const int begin = c;
    while (c + 8 <= n && eight(c) == ~uint64_t(0)) c += 8;
    while (c < n && row[c] != 0) ++c;
    run(begin, c);
  }
}

}  // namespace areagraph

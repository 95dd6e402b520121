#pragma once

#include <cstdint>
#include <cstring>

namespace areagraph {

inline bool HasZeroByte(uint64_t word) {
  return ((word - uint64_t(0x0101010101010101)) & ~word & uint64_t(0x8080808080808080)) != 0;
}

// Calls run(begin, end) for each run [begin, end) of bytes of row[0, n) that
// have a bit of `bit` set (a 0 / 255 mask: 0xff; CellState bytes 0, 1, 2:
// the state's value, or 3 for non-free). Eight bytes at a time across
// long stretches of one kind: a map is mostly such stretches.
template <typename Run>
void ForEachRun(const uint8_t* row, int n, uint8_t bit, Run run) {
  const uint64_t all = bit * uint64_t(0x0101010101010101);
  auto eight = [&](int c) {
    uint64_t word;
    std::memcpy(&word, row + c, sizeof(word));
    return word & all;
  };
  int c = 0;
  while (c < n) {
    while (c + 8 <= n && eight(c) == 0) c += 8;
    while (c < n && (row[c] & bit) == 0) ++c;
    if (c == n) return;
    const int begin = c;
    // Eight bytes that all have a bit of `bit` set: none is zero.
    while (c + 8 <= n && !HasZeroByte(eight(c))) c += 8;
    while (c < n && (row[c] & bit) != 0) ++c;
    run(begin, c);
  }
}

// The runs of non-zero cells of a 0 / 255 mask's row.
template <typename Run>
void ForEachMaskRun(const uint8_t* row, int n, Run run) {
  ForEachRun(row, n, 0xff, run);
}

}  // namespace areagraph

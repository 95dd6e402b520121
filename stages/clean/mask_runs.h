#pragma once

#include <cstdint>
#ifdef __SSE2__
#include <immintrin.h>
#endif

namespace areagraph {

// Calls run(begin, end) for each run [begin, end) of bytes of row[0, n) that
// have a bit of `bit` set (a 0 / 255 mask: 0xff; CellState bytes 0, 1, 2:
// the state's value, or 3 for non-free), in order. Sixty-four bytes at a time
// where SSE2 is: one bit per byte, the runs' ends found by counting trailing
// zeros (a noisy scan's rows are many short runs).
template <typename Run>
void ForEachRun(const uint8_t* row, int n, uint8_t bit, Run run) {
  int begin = -1;  // the open run's first byte, or -1
  int c = 0;
#ifdef __SSE2__
  const __m128i mask = _mm_set1_epi8(char(bit)), zero = _mm_setzero_si128();
  for (; c + 64 <= n; c += 64) {
    uint64_t set = 0;  // bit i: byte c + i has a bit of `bit`
    for (int k = 0; k < 4; ++k) {
      const __m128i bytes = _mm_loadu_si128(reinterpret_cast<const __m128i*>(row + c + 16 * k));
      const int unset = _mm_movemask_epi8(_mm_cmpeq_epi8(_mm_and_si128(bytes, mask), zero));
      set |= uint64_t(~unset & 0xffff) << (16 * k);
    }
    for (int at = 0; at < 64;) {
      // The next change of kind from `at` on: a set byte while no run is
      // open, an unset one while one is.
      const uint64_t rest = (begin < 0 ? set : ~set) >> at;
      if (rest == 0) break;
      at += __builtin_ctzll(rest);
      if (begin < 0) {
        begin = c + at;
      } else {
        run(begin, c + at);
        begin = -1;
      }
    }
  }
#endif
  for (; c < n; ++c) {
    const bool set = (row[c] & bit) != 0;
    if (set && begin < 0) {
      begin = c;
    } else if (!set && begin >= 0) {
      run(begin, c);
      begin = -1;
    }
  }
  if (begin >= 0) run(begin, n);
}

// The runs of non-zero cells of a 0 / 255 mask's row.
template <typename Run>
void ForEachMaskRun(const uint8_t* row, int n, Run run) {
  ForEachRun(row, n, 0xff, run);
}

}  // namespace areagraph

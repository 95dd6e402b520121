#include "stages/merge/row_runs.h"

#ifdef __SSE2__
#include <immintrin.h>
#endif

namespace areagraph {
namespace {

template <typename Cell>
int PiecesOf(const cv::Mat& cells, std::vector<PieceRun>* runs, std::vector<int>* piece_of_run) {
  runs->clear();
  std::vector<size_t> row_start(cells.rows + 1, 0);
  for (int r = 0; r < cells.rows; ++r) {
    row_start[r] = runs->size();
    const Cell* row = cells.ptr<Cell>(r);
    for (int c = 0; c < cells.cols;) {
      const int end = RunEnd(row, c, cells.cols);
      if (row[c] > 0) runs->push_back({r, c, end, static_cast<int>(row[c])});
      c = end;
    }
  }
  row_start[cells.rows] = runs->size();
  int count = 0;
  *piece_of_run = JoinRowRuns(
      *runs, row_start, /*eight_connected=*/false,
      [](const PieceRun& above, const PieceRun& below) { return above.value == below.value; },
      &count);
  return count;
}

}  // namespace

int RunEnd(const int* row, int begin, int cols) {
  const int value = row[begin];
  int c = begin + 1;
#ifdef __SSE2__
  const __m128i same = _mm_set1_epi32(value);
  for (; c + 4 <= cols; c += 4) {
    const __m128i four = _mm_loadu_si128(reinterpret_cast<const __m128i*>(row + c));
    if (_mm_movemask_epi8(_mm_cmpeq_epi32(four, same)) != 0xFFFF) break;
  }
#endif
  while (c < cols && row[c] == value) ++c;
  return c;
}

int RunEnd(const uint8_t* row, int begin, int cols) {
  const uint8_t value = row[begin];
  int c = begin + 1;
#ifdef __SSE2__
  const __m128i same = _mm_set1_epi8(static_cast<char>(value));
  for (; c + 16 <= cols; c += 16) {
    const __m128i sixteen = _mm_loadu_si128(reinterpret_cast<const __m128i*>(row + c));
    if (_mm_movemask_epi8(_mm_cmpeq_epi8(sixteen, same)) != 0xFFFF) break;
  }
#endif
  while (c < cols && row[c] == value) ++c;
  return c;
}

int PiecesOverRuns(const cv::Mat& cells, std::vector<PieceRun>* runs,
                   std::vector<int>* piece_of_run) {
  CV_Assert(cells.type() == CV_8U || cells.type() == CV_32S);
  return cells.type() == CV_8U ? PiecesOf<uint8_t>(cells, runs, piece_of_run)
                               : PiecesOf<int>(cells, runs, piece_of_run);
}

}  // namespace areagraph

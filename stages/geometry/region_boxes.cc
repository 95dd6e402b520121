#include "stages/geometry/region_boxes.h"

#include <algorithm>
#include <climits>
#include <opencv2/imgproc.hpp>
#include <vector>

#ifdef __SSE2__
#include <immintrin.h>
#endif

namespace areagraph {
namespace {

// RunPieces for one cell type.
template <typename Cell>
int RunPiecesOf(const cv::Mat& cells, std::vector<PieceRun>* runs, std::vector<int>* piece_of_run) {
  runs->clear();
  // Where each row's runs start in `runs` (one more entry for the end).
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

cv::Mat LabelBoxes(const cv::Mat& labels, int count) {
  const int width = labels.cols, height = labels.rows;
  // Per label: leftmost and rightmost column, first and last row, cells.
  std::vector<int> left(count, INT_MAX), right(count, INT_MIN), top(count, -1), bottom(count, 0);
  std::vector<int> area(count, 0);
  for (int r = 0; r < height; ++r) {
    const int* row = labels.ptr<int>(r);
    for (int start = 0, c = 0; start < width; start = c) {
      c = RunEnd(row, start, width);
      const int label = row[start];
      if (label < 0 || label >= count) continue;
      left[label] = std::min(left[label], start);
      right[label] = std::max(right[label], c - 1);
      if (top[label] < 0) top[label] = r;
      bottom[label] = r;
      area[label] += c - start;
    }
  }
  cv::Mat stats(count, cv::CC_STAT_MAX, CV_32S);
  for (int label = 0; label < count; ++label) {
    int* out = stats.ptr<int>(label);
    if (area[label] == 0) {
      std::fill(out, out + cv::CC_STAT_MAX, 0);
      continue;
    }
    out[cv::CC_STAT_LEFT] = left[label];
    out[cv::CC_STAT_TOP] = top[label];
    out[cv::CC_STAT_WIDTH] = right[label] - left[label] + 1;
    out[cv::CC_STAT_HEIGHT] = bottom[label] - top[label] + 1;
    out[cv::CC_STAT_AREA] = area[label];
  }
  return stats;
}

int LabelRegionsWithBoxes(const cv::Mat& mask, int connectivity, cv::Mat* labels, cv::Mat* stats) {
  const int count = cv::connectedComponents(mask, *labels, connectivity, CV_32S);
  *stats = LabelBoxes(*labels, count);
  return count;
}

cv::Mat LabelMaskInBox(const cv::Mat& labels, int label, const cv::Rect& box) {
  cv::Mat mask = cv::Mat::zeros(box.height + 2, box.width + 2, CV_8U);
  for (int r = 0; r < box.height; ++r) {
    const int* row = labels.ptr<int>(box.y + r) + box.x;
    uint8_t* out = mask.ptr<uint8_t>(r + 1) + 1;
    for (int c = 0; c < box.width; ++c) {
      if (row[c] == label) out[c] = 255;
    }
  }
  return mask;
}

int RunPieces(const cv::Mat& cells, std::vector<PieceRun>* runs, std::vector<int>* piece_of_run) {
  CV_Assert(cells.type() == CV_8U || cells.type() == CV_32S);
  return cells.type() == CV_8U ? RunPiecesOf<uint8_t>(cells, runs, piece_of_run)
                               : RunPiecesOf<int>(cells, runs, piece_of_run);
}

}  // namespace areagraph

#include "stages/import/png_fast_decoder.h"

#include <zlib.h>

#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <vector>
#ifdef __SSE2__
#include <immintrin.h>
#endif

namespace areagraph {
namespace {

uint32_t BigEndian32(const uint8_t* p) {
  return uint32_t(p[0]) << 24 | uint32_t(p[1]) << 16 | uint32_t(p[2]) << 8 | p[3];
}

// Chunks that change nothing in the grey pixels libpng gives us (no
// background, shift or gamma is asked for).
bool Harmless(const char* type) {
  for (const char* known : {"pHYs", "tIME", "bKGD", "sBIT", "tEXt", "zTXt", "iTXt"}) {
    if (std::memcmp(type, known, 4) == 0) return true;
  }
  return false;
}

// libpng's rgb_to_gray for png_set_rgb_to_gray(png, 1, 0.299, 0.587)
// without gamma: coefficients (c * 32768) / 100000 of the fixed-point 29900
// and 58700, blue the rest of 32768; the sum truncated; grey pixels kept.
constexpr uint32_t kRed = 9797, kGreen = 19234, kBlue = 32768 - kRed - kGreen;

uint8_t Grey(uint8_t r, uint8_t g, uint8_t b) {
  if (r == g && r == b) return r;
  return uint8_t((kRed * r + kGreen * g + kBlue * b) >> 15);
}

int PaethPredictor(int a, int b, int c) {
  const int pa = std::abs(b - c), pb = std::abs(a - c), pc = std::abs(a + b - 2 * c);
  if (pa <= pb && pa <= pc) return a;
  return pb <= pc ? b : c;
}

#ifdef __SSE2__
// The Paeth filter undone a pixel of 3 or 4 bytes at a time, in 16-bit
// lanes (the same choice as PaethPredictor, lane by lane). Reads 4 bytes
// at each pixel of `row` and `prior`: both must have one byte to spare.
void PaethPixels(uint8_t* row, const uint8_t* prior, size_t pixels, int bpp) {
  const __m128i zero = _mm_setzero_si128();
  auto load = [&](const uint8_t* p) {
    uint32_t four;
    std::memcpy(&four, p, 4);
    return _mm_unpacklo_epi8(_mm_cvtsi32_si128(int(four)), zero);
  };
  auto abs16 = [&](__m128i v) { return _mm_max_epi16(v, _mm_sub_epi16(zero, v)); };
  __m128i a = zero, c = zero;
  for (size_t x = 0; x < pixels; ++x) {
    uint8_t* out = row + x * bpp;
    const __m128i b = load(prior + x * bpp);
    const __m128i pa = abs16(_mm_sub_epi16(b, c)), pb = abs16(_mm_sub_epi16(a, c));
    const __m128i pc = abs16(_mm_add_epi16(_mm_sub_epi16(b, c), _mm_sub_epi16(a, c)));
    const __m128i not_a = _mm_or_si128(_mm_cmpgt_epi16(pa, pb), _mm_cmpgt_epi16(pa, pc));
    const __m128i not_b = _mm_cmpgt_epi16(pb, pc);
    const __m128i b_or_c = _mm_or_si128(_mm_andnot_si128(not_b, b), _mm_and_si128(not_b, c));
    const __m128i predicted =
        _mm_or_si128(_mm_andnot_si128(not_a, a), _mm_and_si128(not_a, b_or_c));
    const __m128i value = _mm_and_si128(_mm_add_epi16(load(out), predicted), _mm_set1_epi16(0xff));
    const uint32_t bytes = uint32_t(_mm_cvtsi128_si32(_mm_packus_epi16(value, zero)));
    std::memcpy(out, &bytes, bpp);
    a = value;
    c = b;
  }
}
#endif

// Undoes one row's filter in place (`prior`: the row above, unfiltered;
// zeros for the first row). False for an unknown filter type.
bool Unfilter(int type, uint8_t* row, const uint8_t* prior, size_t length, int bpp) {
  switch (type) {
    case 0:
      return true;
    case 1:
      for (size_t i = bpp; i < length; ++i) row[i] = uint8_t(row[i] + row[i - bpp]);
      return true;
    case 2:
      for (size_t i = 0; i < length; ++i) row[i] = uint8_t(row[i] + prior[i]);
      return true;
    case 3:
      for (size_t i = 0; i < size_t(bpp); ++i) row[i] = uint8_t(row[i] + (prior[i] >> 1));
      for (size_t i = bpp; i < length; ++i) {
        row[i] = uint8_t(row[i] + ((row[i - bpp] + prior[i]) >> 1));
      }
      return true;
    case 4:
#ifdef __SSE2__
      if (bpp >= 3) {
        PaethPixels(row, prior, length / bpp, bpp);
        return true;
      }
#endif
      for (size_t i = 0; i < size_t(bpp); ++i) row[i] = uint8_t(row[i] + prior[i]);
      for (size_t i = bpp; i < length; ++i) {
        row[i] = uint8_t(row[i] + PaethPredictor(row[i - bpp], prior[i], prior[i - bpp]));
      }
      return true;
    default:
      return false;
  }
}

// The concatenated IDAT data of a PNG that passes the checks above, or
// false. Every chunk's CRC is checked, as libpng does.
bool ReadChunks(const std::string& bytes, uint32_t* width, uint32_t* height, int* channels,
                std::vector<uint8_t>* data) {
  const auto* p = reinterpret_cast<const uint8_t*>(bytes.data());
  const size_t size = bytes.size();
  static const uint8_t kSignature[8] = {137, 80, 78, 71, 13, 10, 26, 10};
  if (size < 8 || std::memcmp(p, kSignature, 8) != 0) return false;
  bool header = false, end = false, after_data = false;
  for (size_t at = 8; !end;) {
    if (size - at < 12) return false;
    const uint32_t length = BigEndian32(p + at);
    if (length > size - at - 12) return false;
    const char* type = reinterpret_cast<const char*>(p + at + 4);
    const uint8_t* body = p + at + 8;
    if (crc32(crc32(0, nullptr, 0), p + at + 4, length + 4) != BigEndian32(body + length)) {
      return false;
    }
    if (!header) {
      if (std::memcmp(type, "IHDR", 4) != 0 || length != 13) return false;
      *width = BigEndian32(body);
      *height = BigEndian32(body + 4);
      const int depth = body[8], colour = body[9];
      // Compression, filter method 0; not interlaced.
      if (depth != 8 || body[10] != 0 || body[11] != 0 || body[12] != 0) return false;
      switch (colour) {
        case 0:
          *channels = 1;
          break;
        case 4:
          *channels = 2;
          break;
        case 2:
          *channels = 3;
          break;
        case 6:
          *channels = 4;
          break;
        default:
          return false;
      }
      if (*width == 0 || *height == 0 || *width > (1u << 24) || *height > (1u << 24)) return false;
      header = true;
    } else if (std::memcmp(type, "IDAT", 4) == 0) {
      if (after_data) return false;
      data->insert(data->end(), body, body + length);
    } else if (std::memcmp(type, "IEND", 4) == 0) {
      end = true;
    } else if (!Harmless(type)) {
      return false;
    } else if (!data->empty()) {
      after_data = true;
    }
    at += 12 + size_t(length);
  }
  return header && !data->empty();
}

// Inflates `data` into exactly `size` bytes at `out`: false if the stream
// is damaged, shorter, or longer.
bool InflateExactly(const std::vector<uint8_t>& data, uint8_t* out, size_t size) {
  z_stream stream{};
  if (inflateInit(&stream) != Z_OK) return false;
  // Like libpng here (PNG_IGNORE_ADLER32): the chunk CRCs cover the bytes.
  inflateValidate(&stream, 0);
  stream.next_in = const_cast<Bytef*>(data.data());
  stream.avail_in = uInt(data.size());
  stream.next_out = out;
  stream.avail_out = uInt(size);
  const int status = inflate(&stream, Z_FINISH);
  const bool exact = status == Z_STREAM_END && stream.avail_out == 0 && stream.avail_in == 0;
  inflateEnd(&stream);
  return exact;
}

}  // namespace

bool DecodePlainPngToGrey(const std::string& bytes, cv::Mat* grey) {
  grey->release();
  uint32_t width = 0, height = 0;
  int channels = 0;
  std::vector<uint8_t> data;
  if (!ReadChunks(bytes, &width, &height, &channels, &data)) return false;
  const size_t row_bytes = size_t(width) * channels;
  if (row_bytes + 1 > (size_t(1) << 31) / height) return false;
  // Not zeroed first (inflate writes every byte; fresh pages cost enough),
  // with a byte to spare past the last row for PaethPixels's four-byte reads.
  const size_t raw_size = (row_bytes + 1) * height;
  const std::unique_ptr<uint8_t[]> raw(new uint8_t[raw_size + 1]);
  raw[raw_size] = 0;
  if (!InflateExactly(data, raw.get(), raw_size)) return false;
  std::vector<uint8_t> zeros(row_bytes + 1, 0);
  cv::Mat out(int(height), int(width), CV_8UC1);
  for (uint32_t y = 0; y < height; ++y) {
    uint8_t* row = raw.get() + y * (row_bytes + 1);
    const uint8_t* prior = y == 0 ? zeros.data() : row - row_bytes;
    if (!Unfilter(row[0], row + 1, prior, row_bytes, channels)) return false;
    const uint8_t* in = row + 1;
    uint8_t* pixel = out.ptr<uint8_t>(int(y));
    if (channels == 1) {
      std::memcpy(pixel, in, width);
    } else if (channels == 2) {
      for (uint32_t x = 0; x < width; ++x) pixel[x] = in[2 * x];
    } else {
      for (uint32_t x = 0; x < width; ++x, in += channels) pixel[x] = Grey(in[0], in[1], in[2]);
    }
  }
  *grey = out;
  return true;
}

}  // namespace areagraph

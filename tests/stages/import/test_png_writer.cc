#include "tests/stages/import/test_png_writer.h"

#include <zlib.h>

#include <stdexcept>

namespace areagraph::testing {
namespace {

void AppendBigEndian32(std::string& out, uint32_t value) {
  for (int shift = 24; shift >= 0; shift -= 8) out.push_back(static_cast<char>(value >> shift));
}

void AppendChunk(std::string& png, const std::string& type, const std::string& data) {
  AppendBigEndian32(png, static_cast<uint32_t>(data.size()));
  const std::string typed = type + data;
  png += typed;
  AppendBigEndian32(png, static_cast<uint32_t>(
                             crc32(0, reinterpret_cast<const Bytef*>(typed.data()), typed.size())));
}

std::string Header(uint32_t width, uint32_t height, int bit_depth, int colour_type) {
  std::string ihdr;
  AppendBigEndian32(ihdr, width);
  AppendBigEndian32(ihdr, height);
  ihdr += {static_cast<char>(bit_depth), static_cast<char>(colour_type), 0, 0, 0};
  return ihdr;
}

std::string Deflate(const std::string& raw) {
  uLongf size = compressBound(raw.size());
  std::string out(size, '\0');
  if (compress(reinterpret_cast<Bytef*>(out.data()), &size,
               reinterpret_cast<const Bytef*>(raw.data()), raw.size()) != Z_OK) {
    throw std::runtime_error("zlib compress failed");
  }
  out.resize(size);
  return out;
}

// Scanlines with filter type 0 (none) in front of each row.
std::string Scanlines(int height, int row_bytes, const std::string& pixels) {
  std::string raw;
  for (int row = 0; row < height; ++row) {
    raw.push_back('\0');
    raw += pixels.substr(static_cast<size_t>(row) * row_bytes, row_bytes);
  }
  return raw;
}

std::string Png(const std::string& ihdr,
                const std::vector<std::pair<std::string, std::string>>& extra_chunks,
                const std::string& idat) {
  std::string png("\x89PNG\r\n\x1a\n", 8);
  AppendChunk(png, "IHDR", ihdr);
  for (const auto& [type, data] : extra_chunks) AppendChunk(png, type, data);
  AppendChunk(png, "IDAT", idat);
  AppendChunk(png, "IEND", "");
  return png;
}

}  // namespace

std::string PalettePng(int width, int height, const std::vector<uint8_t>& indices,
                       const std::vector<uint8_t>& palette_rgb, const std::vector<uint8_t>& alpha) {
  std::vector<std::pair<std::string, std::string>> chunks = {
      {"PLTE", std::string(palette_rgb.begin(), palette_rgb.end())}};
  if (!alpha.empty()) chunks.push_back({"tRNS", std::string(alpha.begin(), alpha.end())});
  const std::string pixels(indices.begin(), indices.end());
  return Png(Header(width, height, 8, /*palette*/ 3), chunks,
             Deflate(Scanlines(height, width, pixels)));
}

std::string GreyAlphaPng(int width, int height, const std::vector<uint16_t>& samples,
                         int bit_depth) {
  std::string pixels;
  for (const uint16_t sample : samples) {
    if (bit_depth == 16) pixels.push_back(static_cast<char>(sample >> 8));
    pixels.push_back(static_cast<char>(sample & 0xff));
  }
  const int row_bytes = width * 2 * (bit_depth / 8);
  return Png(Header(width, height, bit_depth, /*grey+alpha*/ 4), {},
             Deflate(Scanlines(height, row_bytes, pixels)));
}

std::string HeaderOnlyPng(uint32_t width, uint32_t height) {
  return Png(Header(width, height, 8, /*grey*/ 0), {}, Deflate(std::string(64, '\0')));
}

}  // namespace areagraph::testing

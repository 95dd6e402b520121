#include "common/png_header.h"

#include <exception>
#include <string>

#include "common/error.h"
#include "common/input_file.h"

namespace areagraph {
namespace {

constexpr std::string_view kPngSignature("\x89PNG\r\n\x1a\n", 8);
// Chunk layout: 4-byte length, 4-byte type, data, 4-byte CRC.
constexpr size_t kChunkOverhead = 12;

uint32_t ReadBigEndian32(std::string_view bytes, size_t offset) {
  uint32_t value = 0;
  for (size_t i = 0; i < 4; ++i) value = (value << 8) | static_cast<uint8_t>(bytes[offset + i]);
  return value;
}

}  // namespace

bool HasPngSignature(std::string_view bytes) {
  return bytes.substr(0, kPngSignature.size()) == kPngSignature;
}

PngHeader ReadPngHeader(std::string_view bytes, std::string_view path) {
  const size_t ihdr = kPngSignature.size();
  if (bytes.size() < ihdr + kChunkOverhead + 13 || bytes.substr(ihdr + 4, 4) != "IHDR") {
    throw InputError("PNG file '" + std::string(path) + "' is truncated or corrupt: no IHDR chunk");
  }
  PngHeader header;
  header.width = ReadBigEndian32(bytes, ihdr + 8);
  header.height = ReadBigEndian32(bytes, ihdr + 12);

  size_t offset = ihdr;
  while (offset + kChunkOverhead <= bytes.size()) {
    const uint64_t length = ReadBigEndian32(bytes, offset);
    const std::string_view type = bytes.substr(offset + 4, 4);
    const uint64_t end = offset + kChunkOverhead + length;
    if (end > bytes.size()) break;
    if (type == "IEND") {
      header.complete = true;
      break;
    }
    offset = static_cast<size_t>(end);
  }
  return header;
}

std::optional<int64_t> PngFilePixels(const std::string& path) {
  // The signature and the IHDR chunk: 8 + 4 + 4 + 13 + 4 bytes.
  constexpr size_t kHeaderBytes = 33;
  std::string bytes;
  try {
    bytes = ReadInputFile(path, "'" + path + "'", kHeaderBytes);  // never waits on a FIFO
  } catch (const InputError&) {
    return std::nullopt;
  }
  if (bytes.size() < kHeaderBytes || !HasPngSignature(bytes)) return std::nullopt;
  try {
    const PngHeader header = ReadPngHeader(bytes, path);
    return int64_t{header.width} * header.height;
  } catch (const std::exception&) {
    return std::nullopt;
  }
}

}  // namespace areagraph

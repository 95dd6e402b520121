#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace areagraph {

// What the chunk structure of a PNG file says, read without decompressing.
struct PngHeader {
  uint32_t width = 0;
  uint32_t height = 0;
  // True when the chunks run without a gap up to an IEND chunk.
  bool complete = false;
};

// True when `bytes` starts with the 8-byte PNG signature.
bool HasPngSignature(std::string_view bytes);

// Reads the IHDR size and walks the chunk lengths, so that decompression
// bombs and truncated files are caught before any pixel is decoded. Throws
// InputError naming `path` when not even the IHDR chunk is complete.
PngHeader ReadPngHeader(std::string_view bytes, std::string_view path);

// The pixels of the file at `path` when it is a PNG, read from its header
// alone; nothing for anything else (a YAML, a missing or truncated file).
std::optional<int64_t> PngFilePixels(const std::string& path);

}  // namespace areagraph

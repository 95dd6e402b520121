#include "store/payload_codec.h"

#include <zstd.h>

#include <memory>

#include "common/error.h"

namespace areagraph {
namespace {

struct CompressionContextDeleter {
  void operator()(ZSTD_CCtx* context) const { ZSTD_freeCCtx(context); }
};
struct DecompressionContextDeleter {
  void operator()(ZSTD_DCtx* context) const { ZSTD_freeDCtx(context); }
};

ZSTD_DCtx* DecompressionContext() {
  thread_local std::unique_ptr<ZSTD_DCtx, DecompressionContextDeleter> context(ZSTD_createDCtx());
  return context.get();
}

}  // namespace

ZSTD_CCtx* PayloadCompressionContext() {
  thread_local std::unique_ptr<ZSTD_CCtx, CompressionContextDeleter> context(ZSTD_createCCtx());
  if (!context) throw StoreError("zstd: out of memory for a compression context");
  return context.get();
}

std::string CompressPayload(std::string_view raw) {
  ZSTD_CCtx* context = PayloadCompressionContext();
  // Not zero-filled: of a bound as large as the payload, the frame touches
  // only its own pages (a 133 MB Voronoi diagram compresses to about 47 MB).
  const size_t bound = ZSTD_compressBound(raw.size());
  const std::unique_ptr<char[]> frame(new char[bound]);
  const size_t size =
      ZSTD_compressCCtx(context, frame.get(), bound, raw.data(), raw.size(), kPayloadZstdLevel);
  if (ZSTD_isError(size)) {
    throw StoreError(std::string("zstd compression failed: ") + ZSTD_getErrorName(size));
  }
  return std::string(frame.get(), size);
}

std::string DecodePayload(std::string_view stored, int64_t codec, uint64_t max_bytes) {
  if (codec == static_cast<int64_t>(PayloadCodec::kNone)) return std::string(stored);
  if (codec != static_cast<int64_t>(PayloadCodec::kZstd)) {
    throw StoreError("unknown payload codec " + std::to_string(codec) +
                     " (written by a newer areagraph?)");
  }
  const unsigned long long size = ZSTD_getFrameContentSize(stored.data(), stored.size());
  if (size == ZSTD_CONTENTSIZE_ERROR || size == ZSTD_CONTENTSIZE_UNKNOWN) {
    throw StoreError("payload is not a zstd frame with a size");
  }
  if (size > max_bytes) {
    throw StoreError("payload's zstd frame claims " + std::to_string(size) + " bytes");
  }
  ZSTD_DCtx* context = DecompressionContext();
  if (context == nullptr) throw StoreError("zstd: out of memory for a decompression context");
  std::string raw(static_cast<size_t>(size), '\0');
  const size_t written =
      ZSTD_decompressDCtx(context, raw.data(), raw.size(), stored.data(), stored.size());
  if (ZSTD_isError(written) || written != raw.size()) {
    throw StoreError(std::string("payload's zstd frame is damaged: ") +
                     (ZSTD_isError(written) ? ZSTD_getErrorName(written) : "short frame"));
  }
  return raw;
}

}  // namespace areagraph

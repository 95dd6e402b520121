#pragma once

#include <zstd.h>

#include <cstdint>
#include <string>
#include <string_view>

namespace areagraph {

// How an artifact's payload is kept in the store (the artifacts.payload_codec
// column). Digests are always of the decoded bytes, so keys, digests and
// merges do not depend on the codec.
enum class PayloadCodec : int64_t {
  kNone = 0,  // stored as it is (every payload written before compression)
  kZstd = 1,  // one zstd frame with its content size
};

// zstd's level 1. On 50 maps of ag-make-collection (2026-12-01, shared
// machine) it keeps 0.152 MB per map of 0.94; level 3 keeps 0.131 MB for twice
// the time (0.51 s against 0.25 s for the 47 MB), level 9 0.118 MB for 7x.
inline constexpr int kPayloadZstdLevel = 1;

// The calling thread's zstd compression context, shared by every payload
// written on the thread: creating one costs more than compressing a small
// artifact. Throws StoreError when zstd is out of memory.
ZSTD_CCtx* PayloadCompressionContext();

// One zstd frame of `raw`, in one call: the reference that the streamed
// encoder (payload_encoder.h) is tested against. Throws StoreError if zstd fails.
std::string CompressPayload(std::string_view raw);

// The raw bytes of a stored payload. Throws StoreError saying what is wrong
// (the caller names the artifact) if the codec is unknown or the frame is
// damaged, truncated or claims more than `max_bytes`.
std::string DecodePayload(std::string_view stored, int64_t codec,
                          uint64_t max_bytes = uint64_t{1} << 32);

}  // namespace areagraph

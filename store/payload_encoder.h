#pragma once

#include <google/protobuf/message_lite.h>

#include <cstdint>
#include <string>
#include <string_view>

namespace areagraph {

// A payload as the store keeps it, made without holding its raw bytes: the
// zstd frame (PayloadCodec::kZstd, with its content size), and the SHA-256
// and size of the raw bytes (what keys, digests and merges use).
struct EncodedPayload {
  std::string frame;
  std::string digest;
  int64_t raw_bytes = 0;
};

// `message` serialized straight into the zstd stream and the hash, through a
// small buffer: no copy of the serialized bytes (133 MB for the Voronoi
// diagram of lab_a tiled 8 x 8). The frame equals CompressPayload of
// SerializeAsString(). Throws StoreError when the message is over 2 GB or
// zstd fails.
EncodedPayload EncodeMessagePayload(const google::protobuf::MessageLite& message);

// The same for bytes already serialized (ag-import's grid, merges, tests).
EncodedPayload EncodeRawPayload(std::string_view raw);

}  // namespace areagraph

#pragma once

#include <google/protobuf/message_lite.h>

#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
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

// Up to this many serialized bytes a message is serialized whole and then
// hashed and compressed in one call each: about a tenth fewer instructions
// in zstd than its stream, for a transient copy of the bytes (5.2 MB at most
// on the 16 maps of areagraph/input, lab_e's Voronoi diagram).
inline constexpr size_t kWholeEncodingMaxBytes = size_t{8} << 20;

// `message` serialized and encoded; above kWholeEncodingMaxBytes through
// 1-MB pieces into the hash and a zstd stream, without a copy of the
// serialized bytes (101 MB for the Voronoi diagram of lab_a tiled 8 x 8);
// where there is a second core, a thread of its own compresses while the
// caller serializes and hashes the next piece. Up to there the frame is CompressPayload of
// SerializeAsString(); the stream's frame (above it, and at every size before) can differ from that
// by a few bytes (5 of the 112 frames of areagraph/input, 1-10 bytes each) and decodes to the same
// bytes. Throws StoreError when the message is over 2 GB or zstd fails. `byte_size`, when given, is
// what message.ByteSizeLong() just returned (its sizes are then cached): the message is not sized
// again.
EncodedPayload EncodeMessagePayload(const google::protobuf::MessageLite& message,
                                    std::optional<size_t> byte_size = std::nullopt);

// The same for bytes already serialized (ag-import's grid, merges, tests).
EncodedPayload EncodeRawPayload(std::string_view raw);

// A message's serialized bytes in a buffer of their own, not zero-filled
// first (the write-behind store's hand-over to its thread).
struct SerializedMessage {
  std::unique_ptr<uint8_t[]> bytes;
  size_t size = 0;
  std::string_view view() const {
    return std::string_view(reinterpret_cast<const char*>(bytes.get()), size);
  }
};

// `message` serialized whole; `byte_size` as for EncodeMessagePayload.
// Throws StoreError as EncodeMessagePayload does.
SerializedMessage SerializeMessage(const google::protobuf::MessageLite& message,
                                   std::optional<size_t> byte_size = std::nullopt);

}  // namespace areagraph

#include "store/payload_encoder.h"

#include <google/protobuf/io/coded_stream.h>
#include <google/protobuf/io/zero_copy_stream.h>
#include <zstd.h>

#include <climits>
#include <memory>
#include <vector>

#include "common/error.h"
#include "store/digest.h"
#include "store/payload_codec.h"

namespace areagraph {
namespace {

// The bytes protobuf writes go, one buffer at a time, into SHA-256 and a
// zstd stream whose frame is pledged `raw_bytes` (so it records its content
// size, as DecodePayload needs).
class EncodingStream : public google::protobuf::io::ZeroCopyOutputStream {
 public:
  explicit EncodingStream(uint64_t raw_bytes)
      : context_(PayloadCompressionContext()), buffer_(kBufferBytes), out_(ZSTD_CStreamOutSize()) {
    Check(ZSTD_CCtx_reset(context_, ZSTD_reset_session_and_parameters));
    Check(ZSTD_CCtx_setParameter(context_, ZSTD_c_compressionLevel, kPayloadZstdLevel));
    Check(ZSTD_CCtx_setPledgedSrcSize(context_, raw_bytes));
    // Reserved, not filled: only the pages the frame uses become resident.
    frame_.reserve(ZSTD_compressBound(raw_bytes));
  }

  bool Next(void** data, int* size) override {
    Feed(used_, ZSTD_e_continue);
    *data = buffer_.data();
    *size = static_cast<int>(buffer_.size());
    used_ = buffer_.size();
    count_ += used_;
    return true;
  }
  void BackUp(int count) override {
    used_ -= count;
    count_ -= count;
  }
  int64_t ByteCount() const override { return count_; }

  // Ends the frame with what is left in the buffer, or with `tail` when the
  // buffer is empty; the stream is not used after.
  EncodedPayload Finish(std::string_view tail = {}) {
    if (used_ > 0) {
      tail = std::string_view(buffer_.data(), used_);
    } else {
      count_ += static_cast<int64_t>(tail.size());
    }
    Feed(tail, ZSTD_e_end);
    EncodedPayload payload;
    payload.frame = std::move(frame_);
    payload.digest = hash_.FinishHex();
    payload.raw_bytes = count_;
    return payload;
  }

 private:
  // 64 KB: protobuf fills it in pieces; zstd keeps its own window.
  static constexpr size_t kBufferBytes = size_t{1} << 16;

  // Passes the first `bytes` of the buffer on.
  void Feed(size_t bytes, ZSTD_EndDirective mode) {
    Feed(std::string_view(buffer_.data(), bytes), mode);
  }
  // Hashes and compresses `bytes`; ZSTD_e_end also ends the frame.
  void Feed(std::string_view bytes, ZSTD_EndDirective mode) {
    hash_.Update(bytes);
    ZSTD_inBuffer in{bytes.data(), bytes.size(), 0};
    size_t remaining = 0;
    do {
      ZSTD_outBuffer out{out_.data(), out_.size(), 0};
      remaining = Check(ZSTD_compressStream2(context_, &out, &in, mode));
      frame_.append(out_.data(), out.pos);
    } while (mode == ZSTD_e_end ? remaining != 0 : in.pos < in.size);
    used_ = 0;
  }

  static size_t Check(size_t result) {
    if (ZSTD_isError(result)) {
      throw StoreError(std::string("zstd compression failed: ") + ZSTD_getErrorName(result));
    }
    return result;
  }

  ZSTD_CCtx* context_;
  std::vector<char> buffer_;
  std::vector<char> out_;
  size_t used_ = 0;
  int64_t count_ = 0;
  std::string frame_;
  Sha256 hash_;
};

// Hashes and compresses bytes that are all in memory: zstd's one call reads
// them in place, where its stream copies them into its window and matches
// across the wrap (ZSTD_compressBlock_fast_extDict). The same frame.
EncodedPayload EncodeWhole(std::string_view raw) {
  EncodedPayload payload;
  payload.digest = Sha256Hex(raw);
  payload.frame = CompressPayload(raw);
  payload.raw_bytes = static_cast<int64_t>(raw.size());
  return payload;
}

// The message's size, as ByteSizeLong caches it for the serializer (or as
// the caller's call to it did).
size_t CheckedByteSize(const google::protobuf::MessageLite& message,
                       std::optional<size_t> byte_size) {
  const size_t raw_bytes = byte_size ? *byte_size : message.ByteSizeLong();
  if (raw_bytes > static_cast<size_t>(INT_MAX)) {
    throw StoreError("the artifact is too big to store (" + std::to_string(raw_bytes) + " bytes)");
  }
  return raw_bytes;
}

// Serializes with the sizes CheckedByteSize just cached: no second pass over
// the message.
SerializedMessage SerializeWithCachedSizes(const google::protobuf::MessageLite& message,
                                           size_t raw_bytes) {
  SerializedMessage raw;
  // Not zero-filled: every byte is written by the serializer.
  raw.bytes.reset(new uint8_t[raw_bytes]);
  raw.size = raw_bytes;
  const uint8_t* end = message.SerializeWithCachedSizesToArray(raw.bytes.get());
  if (end != raw.bytes.get() + raw_bytes) {
    throw StoreError("a " + message.GetTypeName() + " changed size while it was serialized");
  }
  return raw;
}

}  // namespace

SerializedMessage SerializeMessage(const google::protobuf::MessageLite& message,
                                   std::optional<size_t> byte_size) {
  return SerializeWithCachedSizes(message, CheckedByteSize(message, byte_size));
}

EncodedPayload EncodeMessagePayload(const google::protobuf::MessageLite& message,
                                    std::optional<size_t> byte_size) {
  const size_t raw_bytes = CheckedByteSize(message, byte_size);
  if (raw_bytes <= kWholeEncodingMaxBytes) {
    return EncodeWhole(SerializeWithCachedSizes(message, raw_bytes).view());
  }
  EncodingStream stream(raw_bytes);
  {
    google::protobuf::io::CodedOutputStream coded(&stream);
    message.SerializeWithCachedSizes(&coded);
    if (coded.HadError()) throw StoreError("could not serialize a " + message.GetTypeName());
  }
  if (stream.ByteCount() != static_cast<int64_t>(raw_bytes)) {
    throw StoreError("a " + message.GetTypeName() + " changed size while it was serialized");
  }
  return stream.Finish();
}

EncodedPayload EncodeRawPayload(std::string_view raw) { return EncodeWhole(raw); }

}  // namespace areagraph

#include "store/payload_encoder.h"

#include <google/protobuf/io/coded_stream.h>
#include <google/protobuf/io/zero_copy_stream.h>
#include <pthread.h>
#include <zstd.h>

#include <array>
#include <climits>
#include <condition_variable>
#include <exception>
#include <memory>
#include <mutex>
#include <thread>
#include <vector>

#include "common/error.h"
#include "store/digest.h"
#include "store/payload_codec.h"

namespace areagraph {
namespace {

// Compresses pieces of one payload into one zstd frame that is pledged
// `raw_bytes` (so it records its content size, as DecodePayload needs). With
// `threaded`, on a thread of its own: the caller serializes and hashes the
// next piece meanwhile (zstd was about half of a big write's time on the
// calling thread, docs/performance.md, "Writing artifacts"). zstd's buffered
// stream makes the same frame whatever the pieces' sizes, so the frame is the
// one the serial stream made before.
class FrameCompressor {
 public:
  // The pieces in flight: one being filled, the others queued or compressed.
  static constexpr size_t kPieces = 4;
  static constexpr size_t kPieceBytes = size_t{1} << 20;

  FrameCompressor(uint64_t raw_bytes, bool threaded) : raw_bytes_(raw_bytes) {
    // Allocated here, on the caller's thread, as everything the frame keeps:
    // reserved, not filled, so only the pages the frame uses become resident,
    // and never grown by the thread.
    frame_.reserve(ZSTD_compressBound(raw_bytes));
    out_.resize(ZSTD_CStreamOutSize());
    for (auto& piece : pieces_) piece.bytes.reset(new char[kPieceBytes]);
    if (threaded) thread_ = std::thread([this] { Run(); });
  }

  ~FrameCompressor() {
    if (!thread_.joinable()) return;
    {
      const std::lock_guard<std::mutex> lock(mutex_);
      stopping_ = true;
    }
    changed_.notify_all();
    thread_.join();
  }

  // The piece to fill next, once the thread is done with it.
  char* NextPiece() {
    std::unique_lock<std::mutex> lock(mutex_);
    changed_.wait(lock, [&] { return error_ || handed_ - compressed_ < kPieces; });
    if (error_) std::rethrow_exception(error_);
    return pieces_[handed_ % kPieces].bytes.get();
  }

  // Hands over the piece NextPiece gave, with `size` bytes; `last` ends the frame.
  void Hand(size_t size, bool last) {
    if (!thread_.joinable()) {
      Compress(pieces_[0], size, last);
      return;
    }
    {
      const std::lock_guard<std::mutex> lock(mutex_);
      pieces_[handed_ % kPieces].size = size;
      ++handed_;
      ended_ = last;
    }
    changed_.notify_all();
  }

  // The frame, once the last piece is compressed.
  std::string Finish() {
    if (thread_.joinable()) {
      std::unique_lock<std::mutex> lock(mutex_);
      changed_.wait(lock, [&] { return error_ || compressed_ == handed_; });
      if (error_) std::rethrow_exception(error_);
    }
    return std::move(frame_);
  }

 private:
  struct Piece {
    std::unique_ptr<char[]> bytes;
    size_t size = 0;
  };

  void Run() {
    pthread_setname_np(pthread_self(), "ag-store-zstd");  // for top and perf
    try {
      while (true) {
        size_t index = 0;
        bool last = false;
        {
          std::unique_lock<std::mutex> lock(mutex_);
          changed_.wait(lock, [&] { return stopping_ || handed_ > compressed_; });
          if (handed_ == compressed_) return;  // stopping
          index = compressed_;
          last = ended_ && index + 1 == handed_;
        }
        Compress(pieces_[index % kPieces], pieces_[index % kPieces].size, last);
        {
          const std::lock_guard<std::mutex> lock(mutex_);
          ++compressed_;
        }
        changed_.notify_all();
        if (last) return;
      }
    } catch (...) {
      {
        const std::lock_guard<std::mutex> lock(mutex_);
        error_ = std::current_exception();
      }
      changed_.notify_all();
    }
  }

  // Compresses `size` bytes of `piece` (the first call sets the frame up);
  // `last` also ends the frame.
  void Compress(const Piece& piece, size_t size, bool last) {
    if (context_ == nullptr) {
      context_ = PayloadCompressionContext();  // the calling thread's own
      Check(ZSTD_CCtx_reset(context_, ZSTD_reset_session_and_parameters));
      Check(ZSTD_CCtx_setParameter(context_, ZSTD_c_compressionLevel, kPayloadZstdLevel));
      Check(ZSTD_CCtx_setPledgedSrcSize(context_, raw_bytes_));
    }
    const ZSTD_EndDirective mode = last ? ZSTD_e_end : ZSTD_e_continue;
    ZSTD_inBuffer in{piece.bytes.get(), size, 0};
    size_t remaining = 0;
    do {
      ZSTD_outBuffer out{out_.data(), out_.size(), 0};
      remaining = Check(ZSTD_compressStream2(context_, &out, &in, mode));
      frame_.append(out_.data(), out.pos);
    } while (last ? remaining != 0 : in.pos < in.size);
  }

  static size_t Check(size_t result) {
    if (ZSTD_isError(result)) {
      throw StoreError(std::string("zstd compression failed: ") + ZSTD_getErrorName(result));
    }
    return result;
  }

  const uint64_t raw_bytes_;
  ZSTD_CCtx* context_ = nullptr;  // of the thread that compresses
  std::string frame_;
  std::vector<char> out_;
  std::array<Piece, kPieces> pieces_;

  std::mutex mutex_;
  std::condition_variable changed_;
  size_t handed_ = 0;      // pieces handed over
  size_t compressed_ = 0;  // pieces compressed
  bool ended_ = false;     // the last piece is handed over
  bool stopping_ = false;
  std::exception_ptr error_;
  std::thread thread_;  // last: started once the rest is set up
};

// The bytes protobuf writes go, one piece at a time, into SHA-256 here and
// then to the compressor.
class EncodingStream : public google::protobuf::io::ZeroCopyOutputStream {
 public:
  EncodingStream(uint64_t raw_bytes, bool threaded) : compressor_(raw_bytes, threaded) {}

  bool Next(void** data, int* size) override {
    if (piece_ != nullptr) Hand(/*last=*/false);
    piece_ = compressor_.NextPiece();
    *data = piece_;
    *size = static_cast<int>(FrameCompressor::kPieceBytes);
    used_ = FrameCompressor::kPieceBytes;
    count_ += static_cast<int64_t>(used_);
    return true;
  }
  void BackUp(int count) override {
    used_ -= count;
    count_ -= count;
  }
  int64_t ByteCount() const override { return count_; }

  // Ends the frame with what is left in the piece; the stream is not used after.
  EncodedPayload Finish() {
    if (piece_ == nullptr) piece_ = compressor_.NextPiece();
    Hand(/*last=*/true);
    EncodedPayload payload;
    payload.frame = compressor_.Finish();
    payload.digest = hash_.FinishHex();
    payload.raw_bytes = count_;
    return payload;
  }

 private:
  // Hashed here, while the piece is still in this core's cache.
  void Hand(bool last) {
    hash_.Update(std::string_view(piece_, used_));
    compressor_.Hand(used_, last);
    piece_ = nullptr;
    used_ = 0;
  }

  FrameCompressor compressor_;
  char* piece_ = nullptr;  // being filled by protobuf
  size_t used_ = 0;
  int64_t count_ = 0;
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
  // A second core, if any, compresses while this one serializes.
  EncodingStream stream(raw_bytes, std::thread::hardware_concurrency() > 1);
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

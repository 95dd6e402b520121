#include "store/payload_codec.h"

#include <gtest/gtest.h>

#include <random>
#include <string>

#include "common/error.h"

namespace areagraph {
namespace {

constexpr int64_t kNone = static_cast<int64_t>(PayloadCodec::kNone);
constexpr int64_t kZstd = static_cast<int64_t>(PayloadCodec::kZstd);

// Bytes shaped like a serialized graph: repeated field tags, small varints.
std::string GraphLikeBytes(size_t size) {
  std::mt19937 random(7);
  std::string bytes;
  while (bytes.size() < size) {
    bytes += '\x0a';
    bytes += static_cast<char>(random() % 20);
    bytes += static_cast<char>(random() % 4);
  }
  bytes.resize(size);
  return bytes;
}

TEST(PayloadCodecTest, ZstdRoundTripsAndShrinksRepetitiveBytes) {
  const std::string raw = GraphLikeBytes(100000);
  const std::string stored = CompressPayload(raw);
  EXPECT_LT(stored.size(), raw.size() / 2);
  EXPECT_EQ(DecodePayload(stored, kZstd), raw);
}

TEST(PayloadCodecTest, EmptyPayloadRoundTrips) {
  EXPECT_EQ(DecodePayload(CompressPayload(""), kZstd), "");
}

TEST(PayloadCodecTest, UncompressedPayloadIsReturnedAsItIs) {
  const std::string raw = GraphLikeBytes(1000);
  EXPECT_EQ(DecodePayload(raw, kNone), raw);
}

void ExpectStoreError(const std::string& stored, int64_t codec, const std::string& fragment,
                      uint64_t max_bytes = uint64_t{1} << 32) {
  try {
    DecodePayload(stored, codec, max_bytes);
    ADD_FAILURE() << "no error for " << fragment;
  } catch (const StoreError& error) {
    EXPECT_NE(std::string(error.what()).find(fragment), std::string::npos) << error.what();
  }
}

TEST(PayloadCodecTest, DamagedFramesAreStoreErrors) {
  const std::string stored = CompressPayload(GraphLikeBytes(50000));
  ExpectStoreError("not a frame", kZstd, "not a zstd frame");
  ExpectStoreError(stored.substr(0, stored.size() / 2), kZstd, "damaged");
  std::string flipped = stored;
  flipped[flipped.size() / 2] ^= 0x5a;
  flipped[flipped.size() / 2 + 1] ^= 0x33;
  try {
    // A flip inside the entropy-coded block either breaks the frame or yields
    // other bytes, which the store's digest check then catches.
    EXPECT_NE(DecodePayload(flipped, kZstd), GraphLikeBytes(50000));
  } catch (const StoreError& error) {
    EXPECT_NE(std::string(error.what()).find("damaged"), std::string::npos) << error.what();
  }
}

TEST(PayloadCodecTest, FrameClaimingTooManyBytesIsRefusedBeforeAllocating) {
  const std::string stored = CompressPayload(std::string(4096, 'a'));
  ExpectStoreError(stored, kZstd, "frame claims 4096 bytes", /*max_bytes=*/1000);
}

TEST(PayloadCodecTest, UnknownCodecIsRefused) {
  ExpectStoreError("abc", 7, "unknown payload codec 7");
  ExpectStoreError("abc", -1, "unknown payload codec -1");
}

}  // namespace
}  // namespace areagraph

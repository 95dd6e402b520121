#include "store/payload_encoder.h"

#include <gtest/gtest.h>
#include <zstd.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>

#include "proto/artifacts.pb.h"
#include "store/digest.h"
#include "store/payload_codec.h"

namespace areagraph {
namespace {

constexpr int64_t kZstd = static_cast<int64_t>(PayloadCodec::kZstd);

// A diagram of `vertex_count` vertices and as many edges: several MB, so
// that serialization passes many buffers and zstd many blocks and windows.
proto::VoronoiDiagram RandomDiagram(int vertex_count) {
  std::mt19937 random(11);
  std::uniform_real_distribution<double> coordinate(0.0, 4000.0);
  proto::VoronoiDiagram diagram;
  diagram.set_format_version(1);
  for (int v = 0; v < vertex_count; ++v) {
    proto::Point2* site = diagram.add_sites();
    site->set_x(std::floor(coordinate(random)) + 0.5);
    site->set_y(std::floor(coordinate(random)) + 0.5);
    proto::VoronoiVertex* vertex = diagram.add_vertices();
    vertex->mutable_position()->set_x(coordinate(random));
    vertex->mutable_position()->set_y(coordinate(random));
    vertex->set_clearance_px(coordinate(random) / 100);
    proto::VoronoiEdge* edge = diagram.add_edges();
    edge->set_source(v);
    edge->set_target(static_cast<int>(random() % vertex_count));
    edge->set_left_site(static_cast<int>(random() % vertex_count));
    edge->set_right_site(static_cast<int>(random() % vertex_count));
    edge->set_clearance_px(coordinate(random) / 100);
  }
  return diagram;
}

// A frame of `raw` with its size and digest.
void ExpectEncodes(const EncodedPayload& encoded, const std::string& raw) {
  EXPECT_EQ(encoded.raw_bytes, static_cast<int64_t>(raw.size()));
  EXPECT_EQ(encoded.digest, Sha256Hex(raw));
  EXPECT_TRUE(DecodePayload(encoded.frame, kZstd) == raw);
}

// What the store wrote before: the serialized copy, compressed in one go.
void ExpectSameAsOneShot(const EncodedPayload& encoded, const std::string& raw) {
  ExpectEncodes(encoded, raw);
  EXPECT_TRUE(encoded.frame == CompressPayload(raw)) << "the stored bytes changed";
}

// zstd's stream can end up with a frame a few bytes off its one call's (this
// 23-MB diagram; an 11.6-MB one not): a frame of the same bytes.
TEST(PayloadEncoderTest, StreamedMessageEncodesItsBytes) {
  const proto::VoronoiDiagram diagram = RandomDiagram(300000);
  const std::string raw = diagram.SerializeAsString();
  ASSERT_GT(raw.size(), kWholeEncodingMaxBytes);  // the streamed path
  ExpectEncodes(EncodeMessagePayload(diagram), raw);
}

// The frame a serial zstd stream makes of `raw` fed in `piece` bytes at a
// time, as the store's encoder did before it compressed on a second thread
// (64-KB pieces).
std::string SerialStreamFrame(const std::string& raw, size_t piece) {
  ZSTD_CCtx* context = ZSTD_createCCtx();
  ZSTD_CCtx_setParameter(context, ZSTD_c_compressionLevel, kPayloadZstdLevel);
  ZSTD_CCtx_setPledgedSrcSize(context, raw.size());
  std::string frame;
  std::string out(ZSTD_CStreamOutSize(), '\0');
  for (size_t at = 0; at < raw.size(); at += piece) {
    const bool last = at + piece >= raw.size();
    ZSTD_inBuffer in{raw.data() + at, std::min(piece, raw.size() - at), 0};
    size_t remaining = 0;
    do {
      ZSTD_outBuffer to{out.data(), out.size(), 0};
      remaining = ZSTD_compressStream2(context, &to, &in, last ? ZSTD_e_end : ZSTD_e_continue);
      EXPECT_FALSE(ZSTD_isError(remaining));
      frame.append(out.data(), to.pos);
    } while (last ? remaining != 0 : in.pos < in.size);
  }
  ZSTD_freeCCtx(context);
  return frame;
}

// The streamed frame (compressed on a second thread in 1-MB pieces where
// there is a second core) is byte for byte the serial stream's of 64-KB
// pieces: stored payloads keep their bytes.
TEST(PayloadEncoderTest, StreamedFrameEqualsSerialStream) {
  for (const int vertices : {300000, 301234}) {
    const proto::VoronoiDiagram diagram = RandomDiagram(vertices);
    const std::string raw = diagram.SerializeAsString();
    ASSERT_GT(raw.size(), kWholeEncodingMaxBytes);
    const EncodedPayload encoded = EncodeMessagePayload(diagram);
    ExpectEncodes(encoded, raw);
    EXPECT_TRUE(encoded.frame == SerialStreamFrame(raw, size_t{1} << 16)) << vertices;
    EXPECT_TRUE(encoded.frame == SerialStreamFrame(raw, 12345)) << vertices;
  }
}

TEST(PayloadEncoderTest, MessageSerializedWholeEqualsOneShot) {
  const proto::VoronoiDiagram diagram = RandomDiagram(100000);
  const std::string raw = diagram.SerializeAsString();
  ASSERT_GT(raw.size(), size_t{4} << 20);
  ASSERT_LE(raw.size(), kWholeEncodingMaxBytes);
  ExpectSameAsOneShot(EncodeMessagePayload(diagram), raw);
}

// Cells of `width` x `height`, a third of them not free.
proto::GridMap RandomGrid(int width, int height) {
  proto::GridMap grid;
  grid.mutable_frame()->set_width_px(width);
  std::string cells(static_cast<size_t>(width) * height, '\0');
  std::mt19937 random(3);
  for (char& cell : cells) cell = static_cast<char>(random() % 3 == 0 ? random() % 3 : 0);
  grid.set_cells(cells);
  return grid;
}

TEST(PayloadEncoderTest, LongBytesFieldEqualsOneShotOrEncodesItsBytesWhenStreamed) {
  const proto::GridMap small = RandomGrid(1500, 1400);
  ExpectSameAsOneShot(EncodeMessagePayload(small), small.SerializeAsString());
  const proto::GridMap big = RandomGrid(3000, 3000);  // 9 MB: streamed
  ExpectEncodes(EncodeMessagePayload(big), big.SerializeAsString());
}

TEST(PayloadEncoderTest, SmallAndEmptyMessagesEqualOneShot) {
  ExpectSameAsOneShot(EncodeMessagePayload(proto::VoronoiDiagram()), "");
  ExpectSameAsOneShot(EncodeMessagePayload(RandomDiagram(3)), RandomDiagram(3).SerializeAsString());
}

TEST(PayloadEncoderTest, RawBytesEqualOneShot) {
  const std::string raw = RandomDiagram(20000).SerializeAsString();
  ExpectSameAsOneShot(EncodeRawPayload(raw), raw);
  ExpectSameAsOneShot(EncodeRawPayload(""), "");
}

TEST(PayloadEncoderTest, ConsecutiveEncodingsDoNotLeakState) {
  const std::string first = RandomDiagram(1000).SerializeAsString();
  const EncodedPayload again = EncodeRawPayload(first);
  EncodeMessagePayload(RandomDiagram(50000));
  EXPECT_TRUE(EncodeRawPayload(first).frame == again.frame);
}

}  // namespace
}  // namespace areagraph

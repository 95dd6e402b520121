// Decoding raw LCM bytes: whole messages only, and no forged array count
// reaches lcm-gen's decoder (which would allocate what the count says).
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "runner/live/lcm_conversion.h"
#include "runner/live/lcm_message_bounds.h"
#include "stages/match/area_graph_diff.h"
#include "tests/runner/live/lcm_test_maps.h"

namespace areagraph {
namespace {

using testing::ThrowsMessage;

template <typename Message>
std::vector<uint8_t> Encode(const Message& message) {
  std::vector<uint8_t> bytes(message.getEncodedSize());
  EXPECT_EQ(message.encode(bytes.data(), 0, static_cast<int>(bytes.size())),
            static_cast<int>(bytes.size()));
  return bytes;
}

void PutBigEndian(std::vector<uint8_t>& bytes, size_t offset, uint32_t value) {
  for (int i = 0; i < 4; ++i) bytes[offset + i] = static_cast<uint8_t>(value >> (24 - 8 * i));
}

int Size(const std::vector<uint8_t>& bytes) { return static_cast<int>(bytes.size()); }

// The diff between the two versions of MakeTwoVersions, as sent.
areagraph_lcm::area_graph_diff_t DiffMessage() {
  proto::AreaGraph first, second;
  testing::MakeTwoVersions(first, second);
  return ToLcmAreaGraphDiff("lab", "k2", DiffAreaGraphs(first, second), second);
}

TEST(LcmMessageBounds, WalkersAgreeWithTheGeneratedEncoders) {
  const auto grid = Encode(ToLcmGridMap("lab", 7, testing::MakeGridMap()));
  EXPECT_EQ(GridMapEncodedSize(grid.data(), Size(grid)), Size(grid));
  const auto graph = Encode(ToLcmAreaGraph("lab", "key", testing::MakeAreaGraph()));
  EXPECT_EQ(AreaGraphEncodedSize(graph.data(), Size(graph)), Size(graph));
  const auto empty = Encode(areagraph_lcm::area_graph_t{});
  EXPECT_EQ(AreaGraphEncodedSize(empty.data(), Size(empty)), Size(empty));
  const auto diff = Encode(DiffMessage());
  EXPECT_EQ(AreaGraphDiffEncodedSize(diff.data(), Size(diff)), Size(diff));
  const auto empty_diff = Encode(areagraph_lcm::area_graph_diff_t{});
  EXPECT_EQ(AreaGraphDiffEncodedSize(empty_diff.data(), Size(empty_diff)), Size(empty_diff));
}

TEST(LcmMessageDecoding, DecodesDiffsAndRejectsForgedCounts) {
  auto bytes = Encode(DiffMessage());
  const areagraph_lcm::area_graph_diff_t diff =
      DecodeAreaGraphDiffMessage(bytes.data(), Size(bytes));
  EXPECT_EQ(diff.version, 2);
  ASSERT_EQ(diff.changed_areas.size(), 1u);
  EXPECT_EQ(diff.changed_areas[0].area.id, 1);
  EXPECT_TRUE(ThrowsMessage([&] { DecodeAreaGraphDiffMessage(bytes.data(), Size(bytes) - 1); },
                            "truncated or with impossible array sizes"));
  // num_added_areas: after the fingerprint, three strings ("lab", "k2",
  // "first-key"), version and four int64s.
  const size_t num_added_offset = 8 + (4 + 4) + (4 + 3) + 8 + (4 + 10) + 4 * 8;
  ASSERT_EQ(bytes[num_added_offset + 3], 1);
  PutBigEndian(bytes, num_added_offset, 0x7fffffffu);
  EXPECT_TRUE(ThrowsMessage([&] { DecodeAreaGraphDiffMessage(bytes.data(), Size(bytes)); },
                            "impossible array sizes"));
  const auto graph = Encode(ToLcmAreaGraph("lab", "key", testing::MakeAreaGraph()));
  EXPECT_TRUE(ThrowsMessage([&] { DecodeAreaGraphDiffMessage(graph.data(), Size(graph)); },
                            "not a message of type area_graph_diff_t"));
}

TEST(LcmMessageDecoding, DecodesWholeMessages) {
  const auto bytes = Encode(ToLcmGridMap("lab", 7, testing::MakeGridMap()));
  const areagraph_lcm::grid_map_t grid = DecodeGridMapMessage(bytes.data(), Size(bytes));
  EXPECT_EQ(grid.name, "lab");
  EXPECT_EQ(grid.utime, 7);
  EXPECT_EQ(grid.cells.size(), 6u);
  const auto graph_bytes = Encode(ToLcmAreaGraph("lab", "key", testing::MakeAreaGraph()));
  const areagraph_lcm::area_graph_t graph =
      DecodeAreaGraphMessage(graph_bytes.data(), Size(graph_bytes));
  EXPECT_EQ(graph.artifact_key, "key");
  ASSERT_EQ(graph.areas.size(), 2u);
  EXPECT_EQ(graph.areas[0].holes.size(), 1u);
  EXPECT_EQ(graph.passages.at(0).id, 7);
}

TEST(LcmMessageDecoding, RejectsGarbageOtherTypesAndPartialMessages) {
  const std::vector<uint8_t> garbage = {1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12};
  EXPECT_TRUE(ThrowsMessage([&] { DecodeGridMapMessage(garbage.data(), Size(garbage)); },
                            "type fingerprint does not match"));
  EXPECT_TRUE(ThrowsMessage([&] { DecodeGridMapMessage(garbage.data(), 3); }, "only 3 bytes"));
  const auto graph = Encode(ToLcmAreaGraph("lab", "key", testing::MakeAreaGraph()));
  EXPECT_TRUE(ThrowsMessage([&] { DecodeGridMapMessage(graph.data(), Size(graph)); },
                            "not a message of type grid_map_t"));

  auto bytes = Encode(ToLcmGridMap("lab", 7, testing::MakeGridMap()));
  EXPECT_TRUE(ThrowsMessage([&] { DecodeGridMapMessage(bytes.data(), Size(bytes) - 1); },
                            "truncated or with impossible array sizes"));
  bytes.insert(bytes.end(), {0, 0, 0});
  EXPECT_TRUE(ThrowsMessage([&] { DecodeGridMapMessage(bytes.data(), Size(bytes)); },
                            "3 bytes after the message"));
}

TEST(LcmMessageDecoding, RejectsForgedCountsBeforeAllocating) {
  auto grid = Encode(ToLcmGridMap("lab", 7, testing::MakeGridMap()));
  // num_cells follows the fingerprint, utime, four doubles, width and height.
  const size_t num_cells_offset = 8 + 8 + 4 * 8 + 2 * 4;
  for (uint32_t forged : {0x7fffffffu, 0xffffffffu, 7u}) {
    PutBigEndian(grid, num_cells_offset, forged);
    EXPECT_TRUE(ThrowsMessage([&] { DecodeGridMapMessage(grid.data(), Size(grid)); },
                              "impossible array sizes"))
        << forged;
  }

  auto graph = Encode(ToLcmAreaGraph("m", "k", testing::MakeAreaGraph()));
  // The first area's outline point count: after the fingerprint, two strings
  // ("m", "k"), the version, predecessor_key (""), utime, sequence,
  // map_utime, the frame, num_areas, the area's id and kind.
  const size_t num_points_offset =
      8 + (4 + 2) + (4 + 2) + 8 + (4 + 1) + 3 * 8 + 4 * 8 + 2 * 4 + 4 + 4 + 1;
  ASSERT_EQ(graph[num_points_offset + 3], 4);  // the room has 4 points
  PutBigEndian(graph, num_points_offset, 0x10000000u);
  EXPECT_TRUE(ThrowsMessage([&] { DecodeAreaGraphMessage(graph.data(), Size(graph)); },
                            "impossible array sizes"));
}

}  // namespace
}  // namespace areagraph

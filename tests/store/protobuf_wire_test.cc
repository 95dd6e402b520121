// IsWellFormedProtobuf, the schema-free payload check of Verify.
#include "store/protobuf_wire.h"

#include <gtest/gtest.h>

#include <string>

#include "proto/artifacts.pb.h"

namespace areagraph {
namespace {

// A message using every wire type the artifacts use: varints, fixed64
// (doubles), packed and nested length-delimited fields, negative int32s.
std::string RealPayload() {
  proto::CleanedMap map;
  map.set_format_version(1);
  map.mutable_frame()->set_width_px(640);
  map.mutable_frame()->set_resolution_m(0.05);
  map.mutable_frame()->set_origin_x_m(-12.5);
  map.set_cells(std::string(1000, '\x01'));
  for (int cell : {3, -7, 100000}) map.add_removed_outlier_cells(cell);
  return map.SerializeAsString();
}

TEST(ProtobufWireTest, SerializedMessagesAreWellFormed) {
  EXPECT_TRUE(IsWellFormedProtobuf(RealPayload()));
  EXPECT_TRUE(IsWellFormedProtobuf(""));  // an empty message
  proto::VoronoiEdge edge;
  edge.set_target(-1);  // ten-byte varint
  EXPECT_TRUE(IsWellFormedProtobuf(edge.SerializeAsString()));
}

TEST(ProtobufWireTest, DamagedBytesAreNot) {
  const std::string payload = RealPayload();
  EXPECT_FALSE(IsWellFormedProtobuf(payload.substr(0, payload.size() - 1)));  // cut short
  EXPECT_FALSE(IsWellFormedProtobuf(std::string("\x00\x01", 2)));             // field 0
  EXPECT_FALSE(IsWellFormedProtobuf("\x0f"));                                 // wire type 7
  EXPECT_FALSE(
      IsWellFormedProtobuf("\x0a\x05"
                           "abc"));                             // length too long
  EXPECT_FALSE(IsWellFormedProtobuf("\x08\xff\xff"));           // varint unfinished
  EXPECT_FALSE(IsWellFormedProtobuf(std::string(11, '\xff')));  // varint too long
  EXPECT_FALSE(IsWellFormedProtobuf("\x0b"));                   // open group
  EXPECT_FALSE(IsWellFormedProtobuf("\x0b\x14"));               // wrong group end
  EXPECT_TRUE(IsWellFormedProtobuf("\x0b\x08\x01\x0c"));        // a group
  EXPECT_FALSE(IsWellFormedProtobuf("<html>not a payload</html>"));
}

}  // namespace
}  // namespace areagraph

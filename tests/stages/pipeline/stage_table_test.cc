// The stage table's artifact types: the names and format versions that reading
// an artifact checks without protobuf's descriptors agree with the protos.
#include "stages/pipeline/stage_table.h"

#include <google/protobuf/descriptor.h>
#include <google/protobuf/reflection.h>
#include <gtest/gtest.h>

#include <map>
#include <string>

#include "common/error.h"
#include "proto/artifacts.pb.h"
#include "stages/pipeline/stage.h"
#include "tests/support/test_support.h"

namespace areagraph::testing {
namespace {

using google::protobuf::FieldDescriptor;

TEST(StageTableTest, EachRowsTypeNameAndFormatVersionComeFromItsPrototype) {
  std::map<std::string, uint32_t> format_of_type;
  for (const StageDefinition& stage : StageTable()) {
    SCOPED_TRACE(stage.info.name);
    EXPECT_EQ(stage.proto_type, stage.prototype->GetTypeName());
    MessagePtr artifact(stage.prototype->New());
    const FieldDescriptor* field = artifact->GetDescriptor()->FindFieldByName("format_version");
    ASSERT_NE(field, nullptr);
    ASSERT_EQ(field->cpp_type(), FieldDescriptor::CPPTYPE_UINT32);
    artifact->GetReflection()->SetUInt32(artifact.get(), field, stage.format_version + 7);
    EXPECT_EQ(stage.format_version_of(*artifact), stage.format_version + 7);
    const StageDefinition* writer = StageWritingType(*artifact);
    ASSERT_NE(writer, nullptr);
    EXPECT_EQ(writer->proto_type, stage.proto_type);
    EXPECT_EQ(NewArtifactMessage(stage.proto_type)->GetTypeName(), stage.proto_type);
    // CheckFormatVersion asks the first row of a type: rows sharing one
    // (merge and match) must write the same format.
    const auto [known, added] = format_of_type.emplace(stage.proto_type, stage.format_version);
    EXPECT_EQ(known->second, stage.format_version);
  }
  EXPECT_EQ(StageWritingType(proto::MapFrame()), nullptr);
  EXPECT_EQ(NewArtifactMessage("areagraph.proto.MapFrame"), nullptr);
}

// A stored artifact is read only as the type its row names.
TEST(StageTableTest, AnArtifactOfAnotherTypeIsRefused) {
  const std::unique_ptr<ArtifactStore> store = OpenArtifactStore(":memory:");
  proto::GridMap grid;
  grid.set_format_version(kGridMapFormatVersion);
  grid.mutable_frame()->set_width_px(2);
  // A clean stage that wrote a GridMap: its proto_type says so.
  const StageRun run = RunCachedStage(*store, "wrong", StageOf(kCleanStage), {}, {},
                                      [&] { return std::make_unique<proto::GridMap>(grid); });
  const std::string expected = "not a valid areagraph.proto.CleanedMap";
  EXPECT_NE(ErrorOf<StoreError>([&] {
              ReadHeadArtifact<proto::CleanedMap>(*store, "wrong", kCleanStage);
            }).find(expected),
            std::string::npos);
  EXPECT_NE(ErrorOf<StoreError>([&] {
              ReadArtifactAs<proto::CleanedMap>(*store, "wrong", run.cache_key);
            }).find(expected),
            std::string::npos);
  EXPECT_EQ(ReadHeadArtifact<proto::GridMap>(*store, "wrong", kCleanStage).frame().width_px(), 2);
  EXPECT_EQ(ReadArtifactAs<proto::GridMap>(*store, "wrong", run.cache_key).frame().width_px(), 2);
}

}  // namespace
}  // namespace areagraph::testing

#include "stages/common/pipeline_options.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <utility>
#include <vector>

#include "common/error.h"
#include "tests/support/test_support.h"

namespace areagraph {
namespace {

using testing::TempDir;
using testing::WriteFile;

TEST(PipelineOptionsTest, OverrideSetsNestedField) {
  proto::PipelineOptions options;
  ApplyOverride("cut.room_width_m=1.1", &options);
  ApplyOverride("clean.outlier_neighbors=12", &options);
  EXPECT_DOUBLE_EQ(options.cut().room_width_m(), 1.1);
  EXPECT_EQ(options.clean().outlier_neighbors(), 12);
  EXPECT_FALSE(options.cut().has_door_width_m());
}

TEST(PipelineOptionsTest, LaterOverrideWins) {
  proto::PipelineOptions options;
  ApplyOverride("cut.room_width_m=1.1", &options);
  ApplyOverride("cut.room_width_m=2.5", &options);
  EXPECT_DOUBLE_EQ(options.cut().room_width_m(), 2.5);
}

TEST(PipelineOptionsTest, UnknownKeyNamesValidKeys) {
  proto::PipelineOptions options;
  try {
    ApplyOverride("cut.room_widht_m=1.1", &options);
    FAIL() << "expected OptionsError";
  } catch (const OptionsError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("unknown option 'cut.room_widht_m'"), std::string::npos) << message;
    EXPECT_NE(message.find("cut.room_width_m"), std::string::npos) << message;
    EXPECT_NE(message.find("import.resolution_m"), std::string::npos) << message;
  }
  EXPECT_THROW(ApplyOverride("nostage.x=1", &options), OptionsError);
  EXPECT_THROW(ApplyOverride("room_width_m=1", &options), OptionsError);
  EXPECT_THROW(ApplyOverride("cut.room_width_m", &options), OptionsError);
}

TEST(PipelineOptionsTest, WrongTypeIsAnError) {
  proto::PipelineOptions options;
  try {
    ApplyOverride("cut.room_width_m=wide", &options);
    FAIL() << "expected OptionsError";
  } catch (const OptionsError& e) {
    EXPECT_NE(std::string(e.what()).find("expects a double"), std::string::npos) << e.what();
  }
  EXPECT_THROW(ApplyOverride("clean.outlier_neighbors=1.5", &options), OptionsError);
  EXPECT_THROW(ApplyOverride("cut.room_width_open_doors=maybe", &options), OptionsError);
  EXPECT_FALSE(options.clean().has_outlier_neighbors());
}

TEST(PipelineOptionsTest, ValidKeysCoverEveryStageField) {
  const std::vector<std::string> keys = ValidOptionKeys();
  for (const char* key :
       {"import.resolution_m", "clean.robot_width_m", "prune.boundary_alpha_radius_m",
        "prune.min_clearance_m", "cut.room_width_m", "cut.door_width_m", "cut.corridor_width_m"}) {
    EXPECT_NE(std::find(keys.begin(), keys.end(), key), keys.end()) << key;
  }
}

TEST(PipelineOptionsTest, DefaultsReproduceThePaper) {
  proto::PipelineOptions options;
  EXPECT_DOUBLE_EQ(options.clean().robot_width_m(), 0.5);
  EXPECT_EQ(options.clean().outlier_neighbors(), 18);
  // The paper's 0.25 m is in examples/options/paper.pbtxt; the default
  // keeps narrower gaps (docs/quality.md, "Options beyond the paper").
  EXPECT_DOUBLE_EQ(options.prune().min_clearance_m(), 0.15);
  EXPECT_DOUBLE_EQ(options.prune().boundary_alpha_radius_m(), 3.0);
}

TEST(PipelineOptionsTest, ExplicitDefaultGivesSameCanonicalBytes) {
  proto::CutOptions unset, explicit_default, changed;
  explicit_default.set_room_width_m(0);
  changed.set_room_width_m(1.3);
  EXPECT_EQ(CanonicalBytes(unset), CanonicalBytes(explicit_default));
  EXPECT_NE(CanonicalBytes(unset), CanonicalBytes(changed));
  EXPECT_EQ(CanonicalText(unset), CanonicalText(explicit_default));
  EXPECT_NE(CanonicalText(unset).find("room_width_m: 0"), std::string::npos);
}

TEST(PipelineOptionsTest, ReadsTextFormatFile) {
  TempDir dir;
  WriteFile(dir.File("o.pbtxt"), "cut { room_width_m: 0.95 }\nclean { outlier_percent: 3.5 }\n");
  const proto::PipelineOptions options = ReadOptionsFile(dir.File("o.pbtxt"));
  EXPECT_DOUBLE_EQ(options.cut().room_width_m(), 0.95);
  EXPECT_DOUBLE_EQ(options.clean().outlier_percent(), 3.5);
}

TEST(PipelineOptionsTest, BadFileNamesLine) {
  TempDir dir;
  WriteFile(dir.File("bad.pbtxt"), "cut {\n  room_width: 0.95\n}\n");
  try {
    ReadOptionsFile(dir.File("bad.pbtxt"));
    FAIL() << "expected OptionsError";
  } catch (const OptionsError& e) {
    EXPECT_NE(std::string(e.what()).find("line 2"), std::string::npos) << e.what();
  }
  EXPECT_THROW(ReadOptionsFile(dir.File("missing.pbtxt")), InputError);
}

// The text parser would skip a reserved name silently; a removed option is
// refused by name instead; a comment that names it is no use of it.
TEST(PipelineOptionsTest, RemovedOptionIsRefusedByName) {
  TempDir dir;
  WriteFile(dir.File("old.pbtxt"), "merge { keep_closed_doors: false }\n");
  try {
    ReadOptionsFile(dir.File("old.pbtxt"));
    FAIL() << "expected OptionsError";
  } catch (const OptionsError& e) {
    EXPECT_NE(std::string(e.what()).find("'merge.keep_closed_doors' was removed"),
              std::string::npos)
        << e.what();
  }
  WriteFile(dir.File("comment.pbtxt"), "# keep_closed_doors: false\nmerge { min_area_m2: 1 }\n");
  EXPECT_DOUBLE_EQ(ReadOptionsFile(dir.File("comment.pbtxt")).merge().min_area_m2(), 1);
}

// The options folded into carried quantities or other options are refused
// by name too, whichever stage they were in.
TEST(PipelineOptionsTest, FoldedOptionsAreRefusedByName) {
  TempDir dir;
  const std::vector<std::pair<std::string, std::string>> folded{
      {"match { split_joins_inside_share: 0.5 }", "match.split_joins_inside_share"},
      {"match { split_joins_rounds: 4 }", "match.split_joins_rounds"},
      {"match { split_joins_min_opening_m: 0.5 }", "match.split_joins_min_opening_m"},
      {"merge { porous_borders { max_gap_m: 0.5 } }", "merge.porous_borders"},
      {"merge { open_border_clearance_m: 0.15 }", "merge.open_border_clearance_m"},
      {"merge { grow_min_gap_m: 0.5 }", "merge.grow_min_gap_m"}};
  for (const auto& [text, name] : folded) {
    WriteFile(dir.File("old.pbtxt"), text + "\n");
    try {
      ReadOptionsFile(dir.File("old.pbtxt"));
      ADD_FAILURE() << "expected OptionsError for " << text;
    } catch (const OptionsError& e) {
      EXPECT_NE(std::string(e.what()).find("'" + name + "' was removed"), std::string::npos)
          << e.what();
    }
  }
}

// The fields of `message` (and of its messages) that it does not set.
void CollectUnsetFields(const google::protobuf::Message& message, const std::string& prefix,
                        std::vector<std::string>* unset) {
  const google::protobuf::Descriptor* descriptor = message.GetDescriptor();
  const google::protobuf::Reflection* reflection = message.GetReflection();
  for (int i = 0; i < descriptor->field_count(); ++i) {
    const google::protobuf::FieldDescriptor* field = descriptor->field(i);
    if (field->is_repeated()) continue;
    const std::string name = prefix + field->name();
    if (!reflection->HasField(message, field)) {
      unset->push_back(name);
    } else if (field->cpp_type() == google::protobuf::FieldDescriptor::CPPTYPE_MESSAGE) {
      CollectUnsetFields(reflection->GetMessage(message, field), name + ".", unset);
    }
  }
}

// default.pbtxt lists every option with its built-in default (regenerate it
// with `ag-run --print-options` below its comment).
TEST(PipelineOptionsTest, DefaultOptionFileListsEveryDefault) {
  const proto::PipelineOptions options =
      ReadOptionsFile(testing::SourcePath("examples/options/default.pbtxt"));
  std::vector<std::string> unset;
  CollectUnsetFields(options, "", &unset);
  EXPECT_TRUE(unset.empty()) << "default.pbtxt misses " << ::testing::PrintToString(unset);
  EXPECT_EQ(CanonicalText(options), CanonicalText(proto::PipelineOptions()));
}

TEST(PipelineOptionsTest, PaperOptionFileParses) {
  const proto::PipelineOptions paper =
      ReadOptionsFile(testing::SourcePath("examples/options/paper.pbtxt"));
  EXPECT_EQ(paper.merge().min_area_m2(), 0);
  EXPECT_TRUE(paper.merge().cover_removed_obstacles());
}

// Every numeric option key, by reflection, so that a new option is covered.
std::vector<std::string> NumericOptionKeys() {
  std::vector<std::string> keys;
  const google::protobuf::Descriptor* pipeline = proto::PipelineOptions::descriptor();
  for (int i = 0; i < pipeline->field_count(); ++i) {
    const google::protobuf::FieldDescriptor* stage = pipeline->field(i);
    for (int j = 0; j < stage->message_type()->field_count(); ++j) {
      const google::protobuf::FieldDescriptor* field = stage->message_type()->field(j);
      if (field->cpp_type() != google::protobuf::FieldDescriptor::CPPTYPE_BOOL) {
        keys.push_back(stage->name() + "." + field->name());
      }
    }
  }
  return keys;
}

// Non-finite and absurd numbers, as a user could type them.
const char* const kAbsurdNumbers[] = {"nan", "inf", "-inf", "1e308", "-1e308", "-1"};

TEST(PipelineOptionsTest, NoNumericOptionTakesANonFiniteOrAbsurdNumber) {
  const std::vector<std::string> keys = NumericOptionKeys();
  ASSERT_GE(keys.size(), 15u);  // a broken reflection walk finds none
  for (const std::string& key : keys) {
    for (const char* value : kAbsurdNumbers) {
      proto::PipelineOptions options;
      const std::string error =
          testing::ErrorOf<OptionsError>([&] { ApplyOverride(key + "=" + value, &options); });
      EXPECT_NE(error.find(key), std::string::npos) << key << "=" << value << ": " << error;
    }
  }
}

TEST(PipelineOptionsTest, OptionsFileWithANonFiniteOrAbsurdNumberIsRefused) {
  TempDir dir;
  for (const std::string& key : NumericOptionKeys()) {
    const size_t dot = key.find('.');
    for (const char* value : kAbsurdNumbers) {
      const std::string path = dir.File("absurd.pbtxt");
      WriteFile(path, key.substr(0, dot) + " { " + key.substr(dot + 1) + ": " + value + " }\n");
      const std::string error = testing::ErrorOf<OptionsError>([&] { ReadOptionsFile(path); });
      EXPECT_NE(error.find("absurd.pbtxt"), std::string::npos) << key << ": " << value << error;
    }
  }
}

TEST(PipelineOptionsTest, NumbersAtTheirBoundsAreAccepted) {
  proto::PipelineOptions options;
  ApplyOverride("prune.min_clearance_m=0", &options);
  ApplyOverride("prune.boundary_alpha_radius_m=10000", &options);
  ApplyOverride("merge.min_area_m2=1e8", &options);
  ApplyOverride("clean.outlier_percent=99.5", &options);
  EXPECT_EQ(options.prune().boundary_alpha_radius_m(), 10000);
  EXPECT_EQ(testing::ErrorOf<OptionsError>([&] { CheckOptionNumbers(options); }), "");
}

TEST(PipelineOptionsTest, BooleansTakeTrueAndFalseInAnyCaseAndOneAndZero) {
  for (const char* yes : {"true", "TRUE", "True", "1"}) {
    proto::PipelineOptions options;
    ApplyOverride(std::string("merge.cover_removed_obstacles=") + yes, &options);
    EXPECT_TRUE(options.merge().has_cover_removed_obstacles()) << yes;
    EXPECT_TRUE(options.merge().cover_removed_obstacles()) << yes;
  }
  for (const char* no : {"false", "FALSE", "fAlSe", "0"}) {
    proto::PipelineOptions options;
    ApplyOverride(std::string("cut.room_width_open_doors=") + no, &options);
    EXPECT_TRUE(options.cut().has_room_width_open_doors()) << no;
    EXPECT_FALSE(options.cut().room_width_open_doors()) << no;
  }
  for (const char* unclear : {"t", "f", "yes", "2", "", "true "}) {
    proto::PipelineOptions options;
    EXPECT_EQ(testing::ErrorOf<OptionsError>([&] {
                ApplyOverride(std::string("cut.room_width_open_doors=") + unclear, &options);
              }),
              "option 'cut.room_width_open_doors' expects true or false (or 1 or 0), got '" +
                  std::string(unclear) + "'");
  }
}

TEST(PipelineOptionsTest, OptionsFolderIsRefusedNotReadAsDefaults) {
  TempDir dir;
  EXPECT_EQ(testing::ErrorOf<InputError>([&] { ReadOptionsFile(dir.path()); }),
            "options file '" + dir.path() + "' is a folder; name a .pbtxt file");
}

}  // namespace
}  // namespace areagraph

#include <gtest/gtest.h>

#include <string>

#include "common/error.h"
#include "store/artifact_store.h"
#include "tests/support/raw_sqlite.h"
#include "tests/support/test_support.h"

namespace areagraph {
namespace {

using testing::MakeArtifact;

constexpr char kKey[] = "0123456789abcdef0123";

// The message of the StoreError that `read` throws ("" if none).
template <typename Read>
std::string ReadError(Read read) {
  try {
    read();
  } catch (const StoreError& error) {
    return error.what();
  }
  return "";
}

class StoreCorruptionTest : public ::testing::Test {
 protected:
  void SetUp() override {
    path_ = dir_.File("store.db");
    OpenArtifactStore(path_)->WriteArtifact(
        MakeArtifact("lab_a", "clean", kKey, std::string(10000, 'p')));
  }

  // Reopens, as a user would after the file was damaged.
  std::unique_ptr<ArtifactStore> Reopen() { return OpenArtifactStore(path_); }

  testing::TempDir dir_;
  std::string path_;
};

TEST_F(StoreCorruptionTest, ChangedPayloadByteIsReportedNotReturned) {
  testing::FlipPayloadByte(path_, kKey, 5000);
  std::unique_ptr<ArtifactStore> store = Reopen();
  // The flip breaks the zstd frame or changes the bytes it decodes to; the
  // digest catches the latter.
  const std::string prefix =
      "artifact 0123456789ab of map 'lab_a' in store '" + path_ + "' is corrupt (";
  const std::string suffix =
      "); run ag-clean --store " + path_ + " --map lab_a --force to recompute it";
  for (const std::string& error : {ReadError([&] { store->ReadArtifact("lab_a", kKey); }),
                                   ReadError([&] { store->ReadHead("lab_a", "clean"); })}) {
    EXPECT_EQ(error.rfind(prefix, 0), 0u) << error;
    ASSERT_GE(error.size(), suffix.size()) << error;
    EXPECT_EQ(error.substr(error.size() - suffix.size()), suffix) << error;
  }
  // Listing needs no payload and still works, so the user can see what is there.
  ASSERT_EQ(store->ReadArtifactSummaries("lab_a").size(), 1u);
  EXPECT_EQ(store->ReadArtifactSummaries("lab_a")[0].payload_bytes, 10000);
  // Recomputing (writing the same key again) repairs it.
  store->WriteArtifact(MakeArtifact("lab_a", "clean", kKey, std::string(10000, 'p')));
  EXPECT_EQ(store->ReadHead("lab_a", "clean")->payload, std::string(10000, 'p'));
}

TEST_F(StoreCorruptionTest, ReplacedPayloadIsReported) {
  testing::ExecSql(path_, "UPDATE artifacts SET payload = X'00010203'");
  EXPECT_NE(ReadError([&] { Reopen()->ReadHead("lab_a", "clean"); }).find("is corrupt"),
            std::string::npos);
}

TEST_F(StoreCorruptionTest, WrongColumnTypesAreReportedByName) {
  testing::ExecSql(path_, "UPDATE artifacts SET stage_version = 'three'");
  std::string error = ReadError([&] { Reopen()->ReadHead("lab_a", "clean"); });
  EXPECT_NE(error.find("artifacts.stage_version holds TEXT where INTEGER belongs"),
            std::string::npos)
      << error;
  EXPECT_NE(error.find(path_), std::string::npos) << error;

  testing::ExecSql(path_, "UPDATE artifacts SET stage_version = 3, payload = 'text'");
  error = ReadError([&] { Reopen()->ReadArtifact("lab_a", kKey); });
  EXPECT_NE(error.find("artifacts.payload holds TEXT where BLOB belongs"), std::string::npos)
      << error;

  testing::ExecSql(path_, "UPDATE maps SET source_path = X'00ff'");
  error = ReadError([&] { Reopen()->ReadAllMaps(); });
  EXPECT_NE(error.find("maps.source_path holds BLOB where TEXT belongs"), std::string::npos)
      << error;
}

TEST_F(StoreCorruptionTest, NullColumnIsReportedByName) {
  // A hand-edited schema without NOT NULL, then a NULL where text belongs.
  testing::ExecSql(path_,
                   "PRAGMA writable_schema = ON;"
                   "UPDATE sqlite_master SET sql = replace(sql, 'created_at TEXT NOT NULL', "
                   "'created_at TEXT') WHERE name = 'artifacts';");
  testing::ExecSql(path_, "UPDATE artifacts SET created_at = NULL");
  const std::string error = ReadError([&] { Reopen()->ReadArtifactSummaries("lab_a"); });
  EXPECT_NE(error.find("artifacts.created_at holds NULL where TEXT belongs"), std::string::npos)
      << error;
}

}  // namespace
}  // namespace areagraph

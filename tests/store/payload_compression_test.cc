// Schema 5: payloads are kept as zstd frames; digests, keys and merges see the
// decoded bytes, and stores written before keep working.
#include <gtest/gtest.h>

#include <string>

#include "common/error.h"
#include "store/artifact_store.h"
#include "tests/support/raw_sqlite.h"
#include "tests/support/test_support.h"

namespace areagraph {
namespace {

using testing::QueryColumn;

// Well-formed wire format (verify checks it) and compressible like a
// serialized graph: many small length-delimited fields.
std::string GraphLikePayload() {
  std::string payload;
  for (int i = 0; i < 20000; ++i) {
    payload += '\x0a';
    payload += '\x01';
    payload += static_cast<char>('a' + i % 17);
  }
  return payload;
}

TEST(PayloadCompressionTest, WritesZstdFramesAndReadsTheOriginalBytes) {
  testing::TempDir dir;
  const std::string path = dir.File("store.db");
  const std::string payload = GraphLikePayload();
  OpenArtifactStore(path)->WriteArtifact(testing::MakeArtifact("m", "import", "k", payload));

  EXPECT_EQ(QueryColumn(path, "SELECT payload_codec FROM artifacts"),
            std::vector<std::string>{"1"});
  const int64_t stored = std::stoll(QueryColumn(path, "SELECT length(payload) FROM artifacts")[0]);
  EXPECT_LT(stored, static_cast<int64_t>(payload.size()) / 4);

  std::unique_ptr<ArtifactStore> store = OpenArtifactStore(path, StoreMode::kReadOnly);
  const std::optional<ArtifactRecord> head = store->ReadHead("m", "import");
  ASSERT_TRUE(head);
  EXPECT_EQ(head->payload, payload);
  EXPECT_EQ(head->payload_bytes, static_cast<int64_t>(payload.size()));  // the message's size
  EXPECT_EQ(store->ReadArtifactSummaries("m")[0].payload_bytes,
            static_cast<int64_t>(payload.size()));
  EXPECT_EQ(store->ReadArtifact("m", "k")->payload, payload);
  EXPECT_TRUE(store->Verify({"import"}).empty());
}

// A store as schema 4 wrote it (raw payloads, no codec column), holding
// `payload` as the clean head of map "old".
void CreateVersion4Store(const std::string& path, const std::string& payload) {
  OpenArtifactStore(path)->WriteArtifact(testing::MakeArtifact("old", "import", "k4", payload));
  testing::RewriteAsSchema4(path);
}

TEST(PayloadCompressionTest, Version4StoreIsReadAsItIsAndUpgradedKeepingItsRawRows) {
  testing::TempDir dir;
  const std::string path = dir.File("v4.db");
  CreateVersion4Store(path, "\x0a\x01x");
  {
    std::unique_ptr<ArtifactStore> reader = OpenArtifactStore(path, StoreMode::kReadOnly);
    EXPECT_EQ(reader->ReadHead("old", "import")->payload, "\x0a\x01x");
    EXPECT_TRUE(reader->Verify({"import"}).empty());
  }
  EXPECT_EQ(QueryColumn(path, "PRAGMA user_version"), std::vector<std::string>{"4"});

  std::unique_ptr<ArtifactStore> store = OpenArtifactStore(path);
  EXPECT_EQ(QueryColumn(path, "PRAGMA user_version"),
            std::vector<std::string>{std::to_string(kStoreSchemaVersion)});
  EXPECT_EQ(QueryColumn(path, "SELECT payload_codec FROM artifacts"),
            std::vector<std::string>{"0"});
  EXPECT_EQ(store->ReadHead("old", "import")->payload, "\x0a\x01x");
  store->WriteArtifact(testing::MakeArtifact("old", "import2", "k5", GraphLikePayload()));
  EXPECT_EQ(QueryColumn(path, "SELECT payload_codec FROM artifacts ORDER BY id"),
            (std::vector<std::string>{"0", "1"}));
  EXPECT_EQ(store->ReadHead("old", "import2")->payload, GraphLikePayload());
  EXPECT_TRUE(store->Verify({"import", "import2"}).empty());
}

TEST(PayloadCompressionTest, MergeKeepsEachRowsCodecFromOldAndNewStores) {
  testing::TempDir dir;
  const std::string old_path = dir.File("v4.db");
  const std::string new_path = dir.File("v5.db");
  CreateVersion4Store(old_path, "\x0a\x01x");
  OpenArtifactStore(new_path)->WriteArtifact(
      testing::MakeArtifact("new", "import", "k5", GraphLikePayload()));
  const std::string out = dir.File("out.db");
  std::unique_ptr<ArtifactStore> merged = OpenArtifactStore(out);
  merged->MergeFrom(old_path);
  merged->MergeFrom(new_path);
  EXPECT_EQ(merged->ReadHead("old", "import")->payload, "\x0a\x01x");
  EXPECT_EQ(merged->ReadHead("new", "import")->payload, GraphLikePayload());
  EXPECT_EQ(QueryColumn(out, "SELECT payload_codec FROM artifacts ORDER BY id"),
            (std::vector<std::string>{"0", "1"}));
  EXPECT_TRUE(merged->Verify({"import"}).empty());
}

TEST(PayloadCompressionTest, DamagedFrameIsACorruptArtifactNotACrash) {
  testing::TempDir dir;
  const std::string path = dir.File("store.db");
  OpenArtifactStore(path)->WriteArtifact(
      testing::MakeArtifact("m", "import", "k", GraphLikePayload()));
  testing::ExecSql(path, "UPDATE artifacts SET payload = substr(payload, 1, length(payload) / 2)");
  std::unique_ptr<ArtifactStore> store = OpenArtifactStore(path);
  try {
    store->ReadHead("m", "import");
    ADD_FAILURE() << "a truncated frame was read";
  } catch (const StoreError& error) {
    EXPECT_NE(std::string(error.what()).find("artifact k of map 'm'"), std::string::npos)
        << error.what();
    EXPECT_NE(std::string(error.what()).find("is corrupt"), std::string::npos) << error.what();
  }
  const std::vector<VerifyProblem> problems = store->Verify({"import"});
  ASSERT_EQ(problems.size(), 1u);
  EXPECT_NE(problems[0].problem.find("corrupt"), std::string::npos) << problems[0].problem;
  // Bytes that decode cleanly but are not what was written: the digest.
  testing::ExecSql(path, "UPDATE artifacts SET payload_codec = 0, payload = X'0a0178'");
  EXPECT_THROW(
      {
        try {
          store->ReadHead("m", "import");
        } catch (const StoreError& error) {
          EXPECT_NE(std::string(error.what()).find("(payload digest mismatch)"), std::string::npos)
              << error.what();
          throw;
        }
      },
      StoreError);
  testing::ExecSql(path, "UPDATE artifacts SET payload_codec = 9");
  EXPECT_THROW(store->ReadHead("m", "import"), StoreError);
}

}  // namespace
}  // namespace areagraph

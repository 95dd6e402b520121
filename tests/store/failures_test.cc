// Failures recorded by runners, and the payload-free cache lookups.
#include <gtest/gtest.h>

#include <regex>
#include <string>

#include "common/error.h"
#include "store/artifact_store.h"
#include "tests/store/maintenance_helpers.h"
#include "tests/support/raw_sqlite.h"
#include "tests/support/test_support.h"

namespace areagraph {
namespace {

using testing::Artifact;

FailureRecord Failure(const std::string& map_name, const std::string& stage,
                      const std::string& message) {
  FailureRecord failure;
  failure.map_name = map_name;
  failure.stage = stage;
  failure.message = message;
  failure.source_path = "maps/" + map_name + ".png";
  return failure;
}

TEST(FailuresTest, RecordReplaceAndClear) {
  std::unique_ptr<ArtifactStore> store = OpenArtifactStore(":memory:");
  EXPECT_TRUE(store->ReadFailures().empty());
  store->RecordFailure(Failure("lab_b", "cut", "no free cells"));
  store->RecordFailure(Failure("lab_a", "import", "cannot decode 'lab_a.png'"));

  std::vector<FailureRecord> failures = store->ReadFailures();
  ASSERT_EQ(failures.size(), 2u);
  EXPECT_EQ(failures[0].map_name, "lab_a");  // by name
  EXPECT_EQ(failures[0].stage, "import");
  EXPECT_EQ(failures[0].message, "cannot decode 'lab_a.png'");
  EXPECT_EQ(failures[0].source_path, "maps/lab_a.png");
  EXPECT_TRUE(std::regex_match(failures[0].failed_at,
                               std::regex(R"(\d{4}-\d\d-\d\dT\d\d:\d\d:\d\d\.\d{3}Z)")))
      << failures[0].failed_at;
  EXPECT_EQ(failures[1].map_name, "lab_b");

  // One failure per map: the latest replaces the earlier one.
  store->RecordFailure(Failure("lab_b", "merge", "line 1\nline 2"));
  failures = store->ReadFailures();
  ASSERT_EQ(failures.size(), 2u);
  EXPECT_EQ(failures[1].stage, "merge");
  EXPECT_EQ(failures[1].message, "line 1\nline 2");

  store->ClearFailure("lab_a");
  store->ClearFailure("never_failed");  // no-op
  failures = store->ReadFailures();
  ASSERT_EQ(failures.size(), 1u);
  EXPECT_EQ(failures[0].map_name, "lab_b");
}

TEST(FailuresTest, FailuresOutliveTheConnectionAndAreReadOnlyVisible) {
  testing::TempDir dir;
  const std::string path = dir.File("store.db");
  OpenArtifactStore(path)->RecordFailure(Failure("m", "voronoi", "CGAL precondition"));
  std::unique_ptr<ArtifactStore> reader = OpenArtifactStore(path, StoreMode::kReadOnly);
  ASSERT_EQ(reader->ReadFailures().size(), 1u);
  EXPECT_EQ(reader->ReadFailures()[0].message, "CGAL precondition");
  EXPECT_THROW(reader->RecordFailure(Failure("n", "cut", "x")), StoreError);
  EXPECT_THROW(reader->ClearFailure("m"), StoreError);
}

TEST(CacheLookupTest, HeadKeyAndHasArtifact) {
  std::unique_ptr<ArtifactStore> store = OpenArtifactStore(":memory:");
  EXPECT_EQ(store->ReadHeadKey("m", "clean"), std::nullopt);
  EXPECT_FALSE(store->HasArtifact("m", "k1"));
  store->WriteArtifact(Artifact("m", "clean", "k1", {"i"}));
  store->WriteArtifact(Artifact("m", "clean", "k2", {"i"}));
  store->WriteArtifact(Artifact("other", "clean", "k3", {"i"}));
  EXPECT_EQ(store->ReadHeadKey("m", "clean"), "k2");
  EXPECT_EQ(store->ReadHeadKey("m", "voronoi"), std::nullopt);
  EXPECT_TRUE(store->HasArtifact("m", "k1"));
  EXPECT_TRUE(store->HasArtifact("m", "k2"));
  EXPECT_FALSE(store->HasArtifact("m", "k3"));  // another map's
  EXPECT_FALSE(store->HasArtifact("nope", "k1"));
  store->UpdateHead("m", "k1");
  EXPECT_EQ(store->ReadHeadKey("m", "clean"), "k1");
}

TEST(CacheLookupTest, LookupsDoNotReadThePayload) {
  testing::TempDir dir;
  const std::string path = dir.File("store.db");
  OpenArtifactStore(path)->WriteArtifact(Artifact("m", "clean", "key", {"i"}, "some text"));
  testing::FlipPayloadByte(path, "key", 3);
  std::unique_ptr<ArtifactStore> store = OpenArtifactStore(path);
  EXPECT_THROW(store->ReadHead("m", "clean"), StoreError);  // the payload is damaged...
  EXPECT_EQ(store->ReadHeadKey("m", "clean"), "key");       // ...but keys are readable
  EXPECT_TRUE(store->HasArtifact("m", "key"));
}

}  // namespace
}  // namespace areagraph

// ArtifactStore::CollectGarbage: heads and what they were computed from stay.
#include <gtest/gtest.h>

#include <string>

#include "common/error.h"
#include "store/artifact_store.h"
#include "tests/store/maintenance_helpers.h"
#include "tests/support/raw_sqlite.h"
#include "tests/support/test_support.h"

namespace areagraph {
namespace {

using testing::Artifact;
using testing::KeysOf;
using Keys = std::vector<std::string>;

// The payload size of an Artifact with this text.
int64_t Bytes(const std::string& text) {
  return static_cast<int64_t>(testing::ProtoBytes(text).size());
}

TEST(GarbageCollectionTest, KeepsHeadsAndTheirInputsTransitively) {
  std::unique_ptr<ArtifactStore> store = OpenArtifactStore(":memory:");
  // A full chain computed once...
  store->WriteArtifact(Artifact("m", "import", "i1", {"file-1"}, "i1"));
  store->WriteArtifact(Artifact("m", "clean", "c1", {"i1"}, "c1"));
  store->WriteArtifact(Artifact("m", "cut", "u1", {"c1"}, "u1"));
  store->WriteArtifact(Artifact("m", "merge", "g1", {"u1"}, "g1"));
  // ...then the cut recomputed with other options, while the merge head
  // still is the one computed from u1: u1 must stay although it is no head.
  store->WriteArtifact(Artifact("m", "cut", "u2", {"c1"}, "u2"));
  // An abandoned branch: an old import and a clean computed from it.
  store->WriteArtifact(Artifact("m", "import", "i0", {"file-0"}, "old import"));
  store->WriteArtifact(Artifact("m", "clean", "c0", {"i0"}, "old clean"));
  store->WriteArtifact(Artifact("m", "import", "i1", {"file-1"}, "i1"));  // head again
  store->WriteArtifact(Artifact("m", "clean", "c1", {"i1"}, "c1"));
  ASSERT_EQ(store->ReadHeadKey("m", "cut"), "u2");
  ASSERT_EQ(store->ReadHeadKey("m", "merge"), "g1");

  const MaintenanceCounts removed = store->CollectGarbage();
  EXPECT_EQ(removed.artifacts, 2);
  EXPECT_EQ(removed.payload_bytes, Bytes("old import") + Bytes("old clean"));
  EXPECT_EQ(removed.maps, 0);
  EXPECT_EQ(KeysOf(*store, "m"), (Keys{"c1", "g1", "i1", "u1", "u2"}));
  for (const char* stage : {"import", "clean", "cut", "merge"}) {
    EXPECT_TRUE(store->ReadHead("m", stage)) << stage;
  }
  EXPECT_TRUE(store->Verify({"import"}).empty());

  const MaintenanceCounts again = store->CollectGarbage();
  EXPECT_EQ(again.artifacts, 0);
  EXPECT_EQ(again.payload_bytes, 0);
}

TEST(GarbageCollectionTest, InputKeysAreFollowedWithinTheMapOnly) {
  std::unique_ptr<ArtifactStore> store = OpenArtifactStore(":memory:");
  store->WriteArtifact(Artifact("b", "clean", "shared", {"x"}));
  store->WriteArtifact(Artifact("b", "clean", "b-head", {"x"}));  // "shared" is no head of b
  store->WriteArtifact(Artifact("a", "clean", "shared", {"x"}));
  store->WriteArtifact(Artifact("a", "voronoi", "a-v", {"shared"}));
  const MaintenanceCounts removed = store->CollectGarbage();
  EXPECT_EQ(removed.artifacts, 1);
  EXPECT_EQ(KeysOf(*store, "a"), (Keys{"a-v", "shared"}));
  EXPECT_EQ(KeysOf(*store, "b"), Keys{"b-head"});
}

TEST(GarbageCollectionTest, MapsLeftWithoutArtifactsAreDropped) {
  testing::TempDir dir;
  const std::string path = dir.File("store.db");
  {
    std::unique_ptr<ArtifactStore> store = OpenArtifactStore(path);
    store->WriteArtifact(Artifact("kept", "import", "k", {"file"}));
    store->WriteArtifact(Artifact("headless", "import", "h1", {"file"}, "twelve bytes"));
    store->WriteArtifact(Artifact("headless", "clean", "h2", {"h1"}));
  }
  testing::ExecSql(
      path, "DELETE FROM heads WHERE map_id = (SELECT id FROM maps WHERE name = 'headless')");
  std::unique_ptr<ArtifactStore> store = OpenArtifactStore(path);
  const MaintenanceCounts removed = store->CollectGarbage();
  EXPECT_EQ(removed.artifacts, 2);
  EXPECT_EQ(removed.payload_bytes, Bytes("twelve bytes") + Bytes("payload"));
  EXPECT_EQ(removed.maps, 1);
  EXPECT_EQ(testing::MapNames(*store), Keys{"kept"});
  // The deletion is on disk, seen by a new connection.
  EXPECT_EQ(testing::QueryColumn(path, "SELECT count(*) FROM artifacts"), Keys{"1"});
}

TEST(GarbageCollectionTest, ReadOnlyStoreIsRefused) {
  testing::TempDir dir;
  const std::string path = dir.File("store.db");
  OpenArtifactStore(path)->WriteArtifact(Artifact("m", "import", "k", {"file"}));
  EXPECT_THROW(OpenArtifactStore(path, StoreMode::kReadOnly)->CollectGarbage(), StoreError);
}

}  // namespace
}  // namespace areagraph

#include <gtest/gtest.h>

#include <string>

#include "store/artifact_store.h"
#include "store/sqlite_store_maintenance_sql.h"
#include "store/sqlite_store_sql.h"
#include "tests/support/raw_sqlite.h"
#include "tests/support/test_support.h"

namespace areagraph {
namespace {

// The lookups of a pipeline run must use indexes: a store with many maps
// would otherwise read every row on each cache check.
TEST(StoreQueryPlanTest, LookupsUseIndexesWithoutScansOrSorts) {
  testing::TempDir dir;
  const std::string path = dir.File("store.db");
  OpenArtifactStore(path)->WriteArtifact(testing::MakeArtifact("m", "clean", "k", "x"));
  // Cache checks, failures by map, and the per-artifact steps of gc.
  for (const char* sql :
       {store_sql::kReadMap, store_sql::kReadArtifact, store_sql::kReadHead,
        store_sql::kReadArtifactSummaries, store_sql::kReadArtifactRef, store_sql::kReadArtifactId,
        store_sql::kHasArtifact, store_sql::kReadHeadKey, store_sql::kClearFailure,
        store_sql::kReadArtifactInputs, store_sql::kDeleteArtifact}) {
    const std::vector<std::string> plan =
        testing::QueryColumn(path, std::string("EXPLAIN QUERY PLAN ") + sql, 3);
    ASSERT_FALSE(plan.empty()) << sql;
    for (const std::string& step : plan) {
      EXPECT_EQ(step.rfind("SCAN", 0), std::string::npos) << step << "\nin: " << sql;
      EXPECT_EQ(step.find("TEMP B-TREE"), std::string::npos) << step << "\nin: " << sql;
    }
  }
}

}  // namespace
}  // namespace areagraph

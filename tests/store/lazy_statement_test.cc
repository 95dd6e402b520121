#include <gtest/gtest.h>
#include <sqlite3.h>

#include <string>

#include "common/error.h"
#include "store/sqlite_statement.h"

namespace areagraph {
namespace {

// A private in-memory database with one table, closed at the end.
class LazyStatementTest : public ::testing::Test {
 protected:
  void SetUp() override {
    ASSERT_EQ(sqlite3_open(":memory:", &db_), SQLITE_OK);
    ASSERT_EQ(sqlite3_exec(db_, "CREATE TABLE t (x INTEGER); INSERT INTO t VALUES (7)", nullptr,
                           nullptr, nullptr),
              SQLITE_OK);
  }
  void TearDown() override { sqlite3_close(db_); }

  // How many statements the connection holds prepared.
  int PreparedCount() const {
    int count = 0;
    for (sqlite3_stmt* s = sqlite3_next_stmt(db_, nullptr); s != nullptr;
         s = sqlite3_next_stmt(db_, s)) {
      ++count;
    }
    return count;
  }

  sqlite3* db_ = nullptr;
  const std::string path_ = ":memory:";
};

TEST_F(LazyStatementTest, PreparesNothingUntilFirstUseAndThenOnce) {
  LazyStatement read(db_, path_, "SELECT x FROM t", "reading t");
  LazyStatement unused(db_, path_, "SELECT count(*) FROM t", "counting t");
  EXPECT_TRUE(read);
  EXPECT_FALSE(read.prepared());
  EXPECT_EQ(PreparedCount(), 0);
  {
    StatementUse use(*read);
    ASSERT_TRUE(read->Step());
    EXPECT_EQ(read->ColumnInt64(0, "t.x"), 7);
  }
  EXPECT_TRUE(read.prepared());
  EXPECT_FALSE(unused.prepared());
  EXPECT_EQ(PreparedCount(), 1);
  SqliteStatement* first = &*read;
  EXPECT_EQ(&*read, first);  // the same statement again, not a new one
  EXPECT_EQ(PreparedCount(), 1);
}

TEST_F(LazyStatementTest, ABadStatementFailsAtItsFirstUseNamingWhatItIsFor) {
  LazyStatement bad(db_, path_, "SELECT nothing FROM missing_table", "reading the missing table");
  try {
    *bad;
    FAIL() << "preparing a statement on a missing table did not throw";
  } catch (const StoreError& error) {
    EXPECT_NE(std::string(error.what()).find("reading the missing table"), std::string::npos)
        << error.what();
  }
}

TEST_F(LazyStatementTest, AnEmptyStatementIsFalse) {
  const LazyStatement none;
  EXPECT_FALSE(none);
  EXPECT_FALSE(none.prepared());
}

}  // namespace
}  // namespace areagraph

#pragma once

#include <memory>
#include <string>
#include <vector>

#include "store/artifact_store.h"

// Test access to a store file that bypasses ArtifactStore: the SQLite C API
// directly, the way a user editing the file by hand (or bit rot) would.
namespace areagraph::testing {

// Runs `sql` (one or more statements) on the file, creating it if needed;
// throws std::runtime_error.
void ExecSql(const std::string& path, const std::string& sql);

// ExecSql, then every artifact row's digest made again (schema 6): a change
// by hand that the store takes as written by itself, e.g. a creation time
// set to order artifacts in a test.
void ExecSqlAndReseal(const std::string& path, const std::string& sql);

// Holds the file's write lock (BEGIN IMMEDIATE on a connection of its own)
// from construction until Release or destruction: a store's writes wait
// meanwhile (its busy timeout is 10 s). Release may come from another thread.
class WriteLockHolder {
 public:
  explicit WriteLockHolder(const std::string& path);
  ~WriteLockHolder();
  WriteLockHolder(const WriteLockHolder&) = delete;
  WriteLockHolder& operator=(const WriteLockHolder&) = delete;
  void Release();

 private:
  struct Connection;
  std::unique_ptr<Connection> connection_;
};

// Column `column` of every row of `sql`, as text.
std::vector<std::string> QueryColumn(const std::string& path, const std::string& sql,
                                     int column = 0);

// "map stage payload-digest" of every head, sorted: two stores that hold the
// same results give the same list.
std::vector<std::string> HeadDigests(const std::string& path);

// The same list read through ArtifactStore rather than SQL: for a collection
// index, whose rows leave most digests to the shard that holds the payload.
std::vector<std::string> StoreHeadDigests(const std::string& path);

// Turns a store of this build into one as schema 4 wrote it: raw payloads,
// no payload_codec or payload_size column.
void RewriteAsSchema4(const std::string& path);

// Turns a store of this build into one as schema 5 wrote it: no row digests.
void RewriteAsSchema5(const std::string& path);

// Overwrites the one occurrence of `from` in the file's bytes with `to` (of
// the same length), the write-ahead log folded in first: a change that
// SQLite does not see, as bit rot would make it (a table row changed while
// its index still holds the old value). Throws unless `from` occurs once.
void ReplaceOnceInFile(const std::string& path, const std::string& from, const std::string& to);

// Overwrites one byte of the stored artifacts.payload in place (the BLOB API,
// no SQL rewrite), keeping the stored digest; `offset` is taken modulo the
// stored (compressed) size.
void FlipPayloadByte(const std::string& path, const std::string& cache_key, int offset);

// Flips (XOR 0xff) `bytes` bytes at the start of the root page of table or
// index `object_name`, in the file itself (the write-ahead log is folded in
// first), as a failing disk would; SQLite's own checks see it, payload
// digests need not.
void DamageRootPage(const std::string& path, const std::string& object_name, int bytes);

// A small artifact with every field set.
NewArtifact MakeArtifact(const std::string& map_name, const std::string& stage,
                         const std::string& cache_key, const std::string& payload);

}  // namespace areagraph::testing

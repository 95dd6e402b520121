#pragma once

#include <ostream>
#include <string>
#include <vector>

namespace areagraph {

// The subcommands of ag-store. Each prints its report to `out` and returns
// the exit code; errors are thrown (StoreError etc.) for RunCommand.

// Copies every store in `inputs` into `output` (created if needed), one
// transaction per input, and prints per input what was new. All inputs are
// checked before `output` is opened, so a typo creates nothing. A damaged
// input (SQLite's integrity_check, a row or payload that fails its digest) is
// refused by name and adds nothing. A new `output` appears only when every
// input merged; an existing one keeps the inputs merged before the failure.
int MergeStores(const std::string& output, const std::vector<std::string>& inputs,
                std::ostream& out);

// Copies the store into the new file `output` through SQLite's online
// backup: consistent even while runners write, log folded in, so the one
// file is the whole store. Refuses an `output` that exists.
int BackupStore(const std::string& store_path, const std::string& output, std::ostream& out);

// Drops the artifacts no head reaches (with `keep_final`, every artifact but
// the Area Graph heads) and prints what was freed; `vacuum` then gives the
// space back to the file system and prints the file sizes. On a collection
// index: the same in each shard store, then the index written again.
int CollectStoreGarbage(const std::string& store_path, bool keep_final, bool vacuum,
                        std::ostream& out);

// Checks SQLite's structures (quick_check with `quick`, else
// integrity_check) and every artifact; prints one line per problem and a
// summary. Returns 1 when there are problems. `progress` shows a progress
// line on stderr. A collection index is checked with its shards; `shallow`
// (an index only) reads no shard payload.
int VerifyStore(const std::string& store_path, bool progress, bool quick, bool shallow,
                std::ostream& out);

// The failures recorded by runners, as a table or JSON.
int ListStoreFailures(const std::string& store_path, bool json, std::ostream& out);

}  // namespace areagraph

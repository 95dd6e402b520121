#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "proto/run_summary.pb.h"
#include "tests/support/test_support.h"

namespace areagraph::testing {

// Writes `count` random office floors (seeds first_seed, first_seed + 1, ...)
// as <dir>/map_<seed>.png.
void WriteRandomMaps(const std::string& dir, int count, unsigned first_seed);

// Runs ag-run with `args` plus --json and parses the summary; the command's
// output is kept in `result` for messages.
proto::RunSummary RunJson(const std::vector<std::string>& args, CommandResult* result = nullptr);

// Hits and misses of one stage in a summary (0, 0 when it did not run).
struct StageCount {
  int hits = 0;
  int misses = 0;
};
StageCount CountOf(const proto::RunSummary& summary, const std::string& stage);

// The payload digest of each map's merge head in a store, by map name.
std::vector<std::pair<std::string, std::string>> GraphDigests(const std::string& store_path);

// HeadDigests (raw_sqlite.h) of a copy of the store's file alone, without its
// write-ahead log, after SQLite's quick_check of the copy: the same as the
// store's own once everything is folded into the file.
std::vector<std::string> HeadDigestsOfFileAlone(const std::string& store_path);

}  // namespace areagraph::testing

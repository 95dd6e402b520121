#pragma once

#include <string>

namespace areagraph {

// Makes a new store file at `path` when none is there (see
// sqlite_store_creation.cc). True only when this call made it: the file then
// holds the current schema in WAL mode and nothing else, so an open's checks
// (writable, ours, not too new) have nothing to find. False for an existing
// file, ":memory:", or any failure, which the ordinary open reports.
bool CreateNewStoreFile(const std::string& path);

}  // namespace areagraph

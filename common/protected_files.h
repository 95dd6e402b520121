#pragma once

// The files that an output of this process must never replace: the stores
// it has opened, with the files SQLite keeps beside them. A tool that reads
// a store and writes a file (ag-export --out, ag-render --out) would
// otherwise destroy the store when both name the same file, through any
// spelling: "s.db", "./s.db", an absolute path or a symbolic link.

#include <optional>
#include <string>

namespace areagraph {

// Records the store file `path` (which need not exist yet) and its `-wal`,
// `-shm` and `-journal` files as protected for the rest of the process.
// Thread-safe.
void ProtectStoreFile(const std::string& path);

// When writing the file `path` would replace a protected file, the reason in
// words ("it is the store 's.db'", "it is the write-ahead log of the store
// 's.db'"); nullopt otherwise. Symbolic links in `path` are followed.
std::optional<std::string> ProtectedFileReason(const std::string& path);

}  // namespace areagraph

#pragma once

#include <string>

namespace areagraph {

// Rebuilds the store file at `path` so the space of deleted artifacts goes
// back to the file system (SQLite's VACUUM, then a write-ahead-log
// checkpoint). Throws StoreError when `path` is not an areagraph store or is
// busy beyond the timeout. Needs free disk space about the store's size.
void VacuumArtifactStore(const std::string& path);

}  // namespace areagraph

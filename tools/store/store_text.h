#pragma once

#include <cstdint>
#include <ostream>
#include <string>

#include "store/artifact_store.h"

namespace areagraph {

// How ag-store's reports word counts and sizes.

// "1 map", "3 maps".
std::string Plural(int64_t count, const std::string& noun);

// "512 bytes", "3145728 bytes (3.0 MiB)".
std::string FormatBytes(int64_t bytes);

// The store's size on disk: the file and its write-ahead log.
int64_t StoreFileBytes(const std::string& path);

// "removed 3 artifacts (1200 bytes of payload) and 1 empty map", or that
// nothing was removed.
std::string RemovedText(const MaintenanceCounts& removed);

// Shrinks the store file at `path` (VacuumArtifactStore) and prints its size
// before and after, naming it `name`.
void VacuumAndReport(const std::string& path, const std::string& name, std::ostream& out);

}  // namespace areagraph

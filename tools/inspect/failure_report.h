#pragma once

#include <ostream>
#include <vector>

#include "store/artifact_store.h"

namespace areagraph {

// One line per failure: map, stage, time (UTC) and message; or a line saying
// there are none. Shared by `ag-inspect --failures` and `ag-store failures`.
void PrintFailureList(const std::vector<FailureRecord>& failures, std::ostream& out);

// The failures as a JSON array of objects with the fields of FailureRecord.
void PrintFailuresJson(const std::vector<FailureRecord>& failures, std::ostream& out);

// Under the map list: which maps failed and in which stage (nothing if none).
void PrintFailedMapsNote(const std::vector<FailureRecord>& failures, std::ostream& out);

}  // namespace areagraph

#pragma once

#include <functional>
#include <memory>
#include <string>

#include "stages/common/stage_info.h"
#include "store/artifact_store.h"

namespace areagraph {

// The whole main() of a stage executable (ag-clean ... ag-merge): --store,
// --map, --options, --set and --force; options checked before the store is
// opened; the stage run through the cache on the heads of its inputs; one
// line "ag-<stage>: map 'M': <summary>, <ms> ms, key <key> (computed|cached)",
// and HugePageRestartLine's after a restart for a big map (RestartForBigMap).
// Freed heap goes back to the system between the compute's big steps.
// The help text is the stage's description in StageTable().
int RunStageMain(const StageInfo& stage, int argc, char** argv);

// Closes `store` and starts the program again with glibc's huge-page tunable
// (common/process_setup/huge_page_restart.h) when the image that ag-import
// read for `map_name` is a PNG of more than kHugePageRestartPixels (read
// from its header, where the store says it was). Otherwise, or when the
// restart fails, returns with the store as it was (reopened after a failed
// restart).
void RestartForBigMap(std::unique_ptr<ArtifactStore>& store,
                      const std::function<std::unique_ptr<ArtifactStore>()>& open,
                      const std::string& map_name);

}  // namespace areagraph

#pragma once

#include "stages/common/stage_info.h"

namespace areagraph {

// The whole main() of a stage executable (ag-clean ... ag-merge): --store,
// --map, --options, --set and --force; options checked before the store is
// opened; the stage run through the cache on the heads of its inputs; one
// line "ag-<stage>: map 'M': <summary>, <ms> ms, key <key> (computed|cached)".
// The help text is the stage's description in StageTable().
int RunStageMain(const StageInfo& stage, int argc, char** argv);

}  // namespace areagraph

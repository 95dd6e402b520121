#pragma once

#include <functional>
#include <string>

#include "stages/common/stage_info.h"

namespace areagraph {

// Test hook: with AG_RUN_FAULT=crash:<map>:<stage>, the worker process dies
// of SIGSEGV when that stage of that map starts, standing in for a crash
// inside CGAL, so that tests can check that crashes stay isolated. With
// stall:<map>:<stage> the worker waits there until a signal ends it, so that
// a test can cancel a job mid-run at a known point. Either calls
// `before_fault` first: the artifacts written behind (the previous stage's)
// are then in the store, so that a test knows what the store holds.
void MaybeInjectCrash(const std::string& map_name, const StageInfo& stage,
                      const std::function<void()>& before_fault);

}  // namespace areagraph

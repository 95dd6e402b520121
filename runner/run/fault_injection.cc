#include "runner/run/fault_injection.h"

#include <unistd.h>

#include <csignal>
#include <cstdlib>

namespace areagraph {

void MaybeInjectCrash(const std::string& map_name, const StageInfo& stage) {
  static const char* fault = std::getenv("AG_RUN_FAULT");
  if (fault == nullptr) return;
  if (std::string(fault) == "crash:" + map_name + ":" + stage.name) std::raise(SIGSEGV);
  while (std::string(fault) == "stall:" + map_name + ":" + stage.name) pause();
}

}  // namespace areagraph

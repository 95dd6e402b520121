#include "runner/run/fault_injection.h"

#include <csignal>
#include <cstdlib>

namespace areagraph {

void MaybeInjectCrash(const std::string& map_name, const StageInfo& stage) {
  static const char* fault = std::getenv("AG_RUN_FAULT");
  if (fault != nullptr && std::string(fault) == "crash:" + map_name + ":" + stage.name) {
    std::raise(SIGSEGV);
  }
}

}  // namespace areagraph

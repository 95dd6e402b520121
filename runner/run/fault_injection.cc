#include "runner/run/fault_injection.h"

#include <unistd.h>

#include <csignal>
#include <cstdlib>

namespace areagraph {

void MaybeInjectCrash(const std::string& map_name, const StageInfo& stage,
                      const std::function<void()>& before_fault) {
  static const char* fault = std::getenv("AG_RUN_FAULT");
  if (fault == nullptr) return;
  const std::string at = map_name + ":" + stage.name;
  if (std::string(fault) != "crash:" + at && std::string(fault) != "stall:" + at) return;
  before_fault();
  if (std::string(fault) == "crash:" + at) std::raise(SIGSEGV);
  while (true) pause();
}

}  // namespace areagraph

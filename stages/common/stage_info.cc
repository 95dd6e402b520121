#include "stages/common/stage_info.h"

#include "stages/common/pipeline_options.h"
#include "store/cache_key.h"

namespace areagraph {

std::string StageCacheKey(const StageInfo& stage, const google::protobuf::Message& options,
                          const std::vector<std::string>& input_keys) {
  return ComputeCacheKey(stage.name, stage.version, CanonicalBytes(options), input_keys);
}

}  // namespace areagraph

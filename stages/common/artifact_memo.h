#pragma once

#include <google/protobuf/message.h>

#include <map>
#include <memory>
#include <string>
#include <utility>

namespace areagraph {

// The artifacts computed in this process, the latest of each stage: the next
// stages of the same map take them as they are instead of reading, hashing
// and parsing the copy just written to the store (ag-pipeline and ag-run run
// all stages of a map in one process). Each message equals what parsing the
// stored bytes gives.
class ArtifactMemo {
 public:
  // Keeps `artifact`, whose cache key is `cache_key`, as `stage`'s latest.
  void Keep(const std::string& stage, const std::string& cache_key,
            std::shared_ptr<const google::protobuf::Message> artifact) {
    artifacts_[stage] = {cache_key, std::move(artifact)};
  }
  // `stage`'s artifact with `cache_key`, or null when it was not computed here.
  const google::protobuf::Message* Find(const std::string& stage,
                                        const std::string& cache_key) const {
    const auto found = artifacts_.find(stage);
    if (found == artifacts_.end() || found->second.first != cache_key) return nullptr;
    return found->second.second.get();
  }
  // Drops `stage`'s artifact, to free its memory once no later stage reads it.
  void Forget(const std::string& stage) { artifacts_.erase(stage); }

 private:
  std::map<std::string, std::pair<std::string, std::shared_ptr<const google::protobuf::Message>>>
      artifacts_;
};

}  // namespace areagraph

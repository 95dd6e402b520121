#pragma once

#include <google/protobuf/message.h>

#include <map>
#include <memory>
#include <set>
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
  // Marks `stage`'s artifact as read for the last time by the next stage:
  // Acquire then hands it over instead of sharing it, so that the reader
  // can free it before it finishes (prune drops the Voronoi diagram once it
  // has filtered it).
  void MarkLastRead(const std::string& stage) { last_read_.insert(stage); }
  // `stage`'s artifact with `cache_key`, or null when it was not computed
  // here. An artifact marked by MarkLastRead leaves the memo: the caller's
  // pointer is then its only owner.
  std::shared_ptr<const google::protobuf::Message> Acquire(const std::string& stage,
                                                           const std::string& cache_key) {
    const auto found = artifacts_.find(stage);
    if (found == artifacts_.end() || found->second.first != cache_key) return nullptr;
    std::shared_ptr<const google::protobuf::Message> artifact = found->second.second;
    if (last_read_.count(stage) > 0) Forget(stage);
    return artifact;
  }
  // Drops `stage`'s artifact, to free its memory once no later stage reads it.
  void Forget(const std::string& stage) {
    artifacts_.erase(stage);
    last_read_.erase(stage);
  }

 private:
  std::map<std::string, std::pair<std::string, std::shared_ptr<const google::protobuf::Message>>>
      artifacts_;
  std::set<std::string> last_read_;
};

}  // namespace areagraph

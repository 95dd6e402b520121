#include "tools/store/collection_commands.h"

#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <filesystem>
#include <memory>

#include "common/error.h"
#include "stages/common/output_file.h"
#include "stages/pipeline/stage_table.h"
#include "store/artifact_store.h"
#include "store/collection_index.h"
#include "tools/store/new_store_file.h"
#include "tools/store/store_text.h"

namespace areagraph {
namespace {

std::string JoinWords(const std::vector<std::string>& words, const std::string& last) {
  std::string joined;
  for (size_t i = 0; i < words.size(); ++i) {
    if (i > 0) joined += i + 1 == words.size() ? " " + last + " " : ", ";
    joined += words[i];
  }
  return joined;
}

void RemoveTemporary(const std::string& path) {
  for (const char* suffix : {"", "-journal", "-wal", "-shm"}) ::unlink((path + suffix).c_str());
}

// Writes the index of `shards` beside `output` under a temporary name and
// renames it over `output`, so that readers see the old index or the new one.
std::vector<CollectionShard> WriteIndexInPlace(const std::string& output,
                                               const std::vector<std::string>& shards,
                                               const std::vector<std::string>& head_stages) {
  if (!NothingAt(output) && !IsCollectionIndex(output)) {
    throw StoreError("'" + output +
                     "' exists and is not a collection index; name a new file (or an index to "
                     "write again)");
  }
  const std::filesystem::path target(output);
  const std::filesystem::path folder = target.has_parent_path() ? target.parent_path() : ".";
  const std::string temporary =
      (folder / ("." + target.filename().string() + "." + std::to_string(::getpid()) + ".tmp"))
          .string();
  RemoveTemporary(temporary);  // left by a killed run of this process id
  try {
    std::vector<CollectionShard> written =
        WriteCollectionIndex(temporary, output, shards, head_stages, FinalStageNames());
    if (::rename(temporary.c_str(), output.c_str()) != 0) {
      throw StoreError("cannot write '" + output + "': " + ErrnoText(errno));
    }
    return written;
  } catch (...) {
    RemoveTemporary(temporary);
    throw;
  }
}

void PrintIndexed(const std::string& output, const std::vector<CollectionShard>& shards,
                  const std::vector<std::string>& head_stages, std::ostream& out) {
  int64_t maps = 0, artifacts = 0;
  for (const CollectionShard& shard : shards) {
    out << shard.path << ": " << Plural(shard.maps, "map") << ", "
        << Plural(shard.artifacts, "artifact") << "\n";
    maps += shard.maps;
    artifacts += shard.artifacts;
  }
  out << "indexed " << Plural(static_cast<int64_t>(shards.size()), "shard store") << " ("
      << Plural(maps, "map") << ", " << Plural(artifacts, "artifact")
      << (head_stages.empty() ? "" : ": the heads of " + JoinWords(head_stages, "and")) << ") into "
      << output << "\n";
}

}  // namespace

std::vector<std::string> FinalStageNames() {
  const std::string graph_type = StageOf(FinalStage()).proto_type;
  std::vector<std::string> names;
  for (const StageDefinition& stage : StageTable()) {
    if (stage.proto_type == graph_type) names.push_back(stage.info.name);
  }
  return names;
}

int IndexCollection(const std::string& output, const std::vector<std::string>& shards,
                    CollectionScope scope, std::ostream& out) {
  const std::vector<std::string> head_stages =
      scope == CollectionScope::kFinal ? FinalStageNames() : std::vector<std::string>{};
  PrintIndexed(output, WriteIndexInPlace(output, shards, head_stages), head_stages, out);
  return 0;
}

int CollectCollectionGarbage(const std::string& index, CollectionScope keep, bool vacuum,
                             std::ostream& out) {
  const CollectionIndexInfo info = ReadCollectionIndexInfo(index);
  std::vector<std::string> shards;
  for (const CollectionShard& shard : info.shards) {
    // Every shard opens (exists, is a store this build reads) before any changes.
    OpenArtifactStore(shard.resolved_path, StoreMode::kReadOnly);
    shards.push_back(shard.resolved_path);
  }
  for (const CollectionShard& shard : info.shards) {
    const MaintenanceCounts removed =
        keep == CollectionScope::kFinal ? KeepOnlyHeadsOf(shard.resolved_path, FinalStageNames())
                                        : OpenArtifactStore(shard.resolved_path)->CollectGarbage();
    out << shard.path << ": " << RemovedText(removed) << "\n";
    if (vacuum) VacuumAndReport(shard.resolved_path, shard.path, out);
  }
  const std::vector<std::string> head_stages =
      keep == CollectionScope::kFinal ? FinalStageNames() : info.head_stages;
  PrintIndexed(index, WriteIndexInPlace(index, shards, head_stages), head_stages, out);
  return 0;
}

int KeepFinalArtifacts(const std::string& store_path, std::ostream& out) {
  out << RemovedText(KeepOnlyHeadsOf(store_path, FinalStageNames())) << "; kept the heads of "
      << JoinWords(FinalStageNames(), "and")
      << "; a later run of these maps computes the other stages again\n";
  return 0;
}

std::vector<std::string> ExpandCollectionIndexes(const std::vector<std::string>& inputs) {
  std::vector<std::string> stores;
  for (const std::string& input : inputs) {
    if (!IsCollectionIndex(input)) {
      stores.push_back(input);
      continue;
    }
    for (const CollectionShard& shard : ReadCollectionIndexInfo(input).shards) {
      stores.push_back(shard.resolved_path);
    }
  }
  return stores;
}

}  // namespace areagraph

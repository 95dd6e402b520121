#pragma once

#include <ostream>
#include <string>
#include <vector>

namespace areagraph {

// The subcommands of ag-store for collections of shard stores behind a
// collection index (store/collection_index.h). Each prints its report to
// `out` and returns the exit code; errors are thrown for RunCommand.

// What `--only` of ag-store index and `--keep` of gc accept: every artifact,
// or only the final stages' heads (the Area Graphs).
enum class CollectionScope { kAll, kFinal };

// The stages whose heads are a map's Area Graph (merge and match): what
// --only final indexes and --keep final keeps.
std::vector<std::string> FinalStageNames();

// Writes the index of `shards` at `output`: a new file, or the index that is
// there (replaced whole, e.g. after a shard was run again; a store that is
// not an index is refused). The file appears only complete.
int IndexCollection(const std::string& output, const std::vector<std::string>& shards,
                    CollectionScope scope, std::ostream& out);

// ag-store gc on an index: garbage collection in every shard it names (or,
// with kFinal, every artifact but the final heads dropped), `vacuum` each,
// then the index written again over the trimmed shards. Every shard is
// opened before any is changed.
int CollectCollectionGarbage(const std::string& index, CollectionScope keep, bool vacuum,
                             std::ostream& out);

// ag-store gc --keep final on one store.
int KeepFinalArtifacts(const std::string& store_path, std::ostream& out);

// The stores to merge for `inputs`: an index stands for its shard stores.
std::vector<std::string> ExpandCollectionIndexes(const std::vector<std::string>& inputs);

}  // namespace areagraph

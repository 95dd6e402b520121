// ag-store verify of a collection index: the index file, each shard store's
// own check, and whether each shard still holds what the index says.

#include <sqlite3.h>

#include <algorithm>
#include <filesystem>
#include <map>
#include <set>

#include "common/error.h"
#include "common/text.h"
#include "store/collection_index_sql.h"
#include "store/collection_index_store.h"

namespace areagraph {
namespace {

constexpr char kChanged[] =
    ": the shard changed after the index was written; run ag-store index again";

std::string ShardName(const CollectionShard& shard) { return "shard store '" + shard.path + "'"; }

std::string KeyOrNone(const std::optional<std::string>& key) {
  return key ? ShortKey(*key) : std::string("none");
}

}  // namespace

std::vector<std::string> CollectionIndexStore::MapNamesOf(int64_t shard_id) {
  SqliteStatement names(db_, path_, collection_sql::kReadShardMapNames, "listing a shard's maps");
  StatementUse use(names);
  names.BindInt64(1, shard_id);
  std::vector<std::string> found;
  while (names.Step()) found.push_back(names.ColumnText(0, "maps.name"));
  return found;
}

std::vector<VerifyProblem> CollectionIndexStore::Verify(
    const std::vector<std::string>& file_input_stages,
    const std::function<void(int64_t, int64_t)>& progress, StructureCheck structure) {
  return VerifyCollection(file_input_stages, progress, structure, ShardCheck::kFull);
}

std::vector<VerifyProblem> CollectionIndexStore::VerifyCollection(
    const std::vector<std::string>& file_input_stages,
    const std::function<void(int64_t, int64_t)>& progress, StructureCheck structure,
    ShardCheck check) {
  std::vector<VerifyProblem> problems;
  try {
    SqliteStatement integrity(db_, path_,
                              structure == StructureCheck::kFull ? collection_sql::kIntegrityCheck
                                                                 : collection_sql::kQuickCheck,
                              "checking the SQLite structure of the index");
    StatementUse use(integrity);
    while (integrity.Step()) {
      const std::string row = integrity.ColumnText(0, "integrity_check");
      if (row != "ok") problems.push_back({"", "", "", "collection index: SQLite: " + row});
    }
  } catch (const StoreError& error) {
    problems.push_back({"", "", "", std::string("collection index: ") + error.what()});
    return problems;  // the rows below cannot be trusted
  }
  int64_t total = 0, done = 0;
  for (const CollectionShard& shard : info_.shards) total += shard.artifacts;
  for (const CollectionShard& shard : info_.shards) {
    CheckShard(shard, file_input_stages, structure, check, total, done, progress, problems);
  }
  return problems;
}

void CollectionIndexStore::CheckShard(const CollectionShard& shard,
                                      const std::vector<std::string>& file_input_stages,
                                      StructureCheck structure, ShardCheck check, int64_t total,
                                      int64_t& done,
                                      const std::function<void(int64_t, int64_t)>& progress,
                                      std::vector<VerifyProblem>& problems) {
  const std::vector<std::string> maps = MapNamesOf(shard.id);
  const std::string first_map = maps.empty() ? "" : maps.front();
  const auto skip = [&] {
    done += shard.artifacts;
    if (progress) progress(done, std::max(total, done));
  };
  if (!std::filesystem::exists(shard.resolved_path)) {
    std::string which = maps.empty() ? "" : " ('" + first_map + "'";
    if (maps.size() > 1) which += " and " + std::to_string(maps.size() - 1) + " more";
    if (!maps.empty()) which += ")";
    problems.push_back({first_map, "", "",
                        ShardName(shard) + " is missing (no file '" + shard.resolved_path +
                            "'): the index's " + std::to_string(maps.size()) + " maps in it" +
                            which + " cannot be read"});
    return skip();
  }
  ArtifactStore* store = nullptr;
  try {
    store = &Shard(shard.id, first_map);
  } catch (const StoreError& error) {
    problems.push_back({first_map, "", "", error.what()});
    return skip();
  }
  if (check == ShardCheck::kFull) {
    // An index of some stages' heads covers those artifacts, not their
    // inputs, which gc --keep final drops from the shards.
    std::vector<std::string> unchecked_inputs = file_input_stages;
    unchecked_inputs.insert(unchecked_inputs.end(), info_.head_stages.begin(),
                            info_.head_stages.end());
    const int64_t base = done;
    for (VerifyProblem& problem : store->Verify(
             unchecked_inputs,
             [&](int64_t shard_done, int64_t) {
               done = base + shard_done;
               if (progress) progress(done, std::max(total, done));
             },
             structure)) {
      problem.problem = "in " + ShardName(shard) + ": " + problem.problem;
      problems.push_back(std::move(problem));
    }
  }
  try {
    CheckIndexedRows(shard, *store, check, total, done, progress, problems);
    CheckHeadsAndMaps(shard, *store, problems);
  } catch (const StoreError& error) {  // damage that stops the reading itself
    problems.push_back({first_map, "", "",
                        "cannot compare " + ShardName(shard) + " with the index: " + error.what()});
  }
}

void CollectionIndexStore::CheckIndexedRows(const CollectionShard& shard, ArtifactStore& store,
                                            ShardCheck check, int64_t total, int64_t& done,
                                            const std::function<void(int64_t, int64_t)>& progress,
                                            std::vector<VerifyProblem>& problems) {
  SqliteStatement rows(db_, path_, collection_sql::kReadShardArtifacts,
                       "listing the artifacts of a shard");
  StatementUse use(rows);
  rows.BindInt64(1, shard.id);
  while (rows.Step()) {
    const std::string map_name = rows.ColumnText(0, "maps.name");
    const IndexedArtifact row = ReadIndexedRow(rows, map_name, 1);
    const ArtifactRecord& indexed = row.record;
    // A row without details is only looked up: its digest would be read past
    // the payload's pages.
    std::optional<ArtifactRecord> stored;
    if (row.detailed) {
      stored = store.ReadArtifactSummary(map_name, indexed.cache_key);
    } else if (store.HasArtifact(map_name, indexed.cache_key)) {
      stored = indexed;
    }
    if (!stored) {
      problems.push_back({map_name, indexed.stage, indexed.cache_key,
                          "not in " + ShardName(shard) + " any more" + kChanged});
    } else if (stored->payload_digest != indexed.payload_digest) {
      problems.push_back({map_name, indexed.stage, indexed.cache_key,
                          ShardName(shard) + " holds another payload under this key" + kChanged});
    }
    if (check == ShardCheck::kIndexedRowsOnly) {
      ++done;
      if (progress) progress(done, std::max(total, done));
    }
  }
}

void CollectionIndexStore::CheckHeadsAndMaps(const CollectionShard& shard, ArtifactStore& store,
                                             std::vector<VerifyProblem>& problems) {
  std::vector<std::string> stages = info_.head_stages;
  if (stages.empty()) {
    SqliteStatement distinct(db_, path_, collection_sql::kReadHeadStages, "listing head stages");
    StatementUse use(distinct);
    while (distinct.Step()) stages.push_back(distinct.ColumnText(0, "heads.stage"));
  }
  std::map<std::string, std::map<std::string, std::string>> indexed_heads;
  for (const std::string& name : MapNamesOf(shard.id)) indexed_heads[name];
  {
    SqliteStatement heads(db_, path_, collection_sql::kReadShardHeads, "listing a shard's heads");
    StatementUse use(heads);
    heads.BindInt64(1, shard.id);
    while (heads.Step()) {
      indexed_heads[heads.ColumnText(0, "maps.name")][heads.ColumnText(1, "heads.stage")] =
          heads.ColumnText(2, "artifacts.cache_key");
    }
  }
  for (const auto& [map_name, heads] : indexed_heads) {
    for (const std::string& stage : stages) {
      const auto found = heads.find(stage);
      const std::optional<std::string> in_index =
          found == heads.end() ? std::nullopt : std::optional<std::string>(found->second);
      const std::optional<std::string> in_shard = store.ReadHeadKey(map_name, stage);
      if (in_index == in_shard) continue;
      problems.push_back({map_name, stage, in_index.value_or(""),
                          "head in " + ShardName(shard) + ": " + KeyOrNone(in_shard) +
                              ", in the index: " + KeyOrNone(in_index) + kChanged});
    }
  }
  for (const MapRecord& map : store.ReadAllMaps()) {
    if (indexed_heads.count(map.name) > 0) continue;
    const bool has_indexed_stage =
        std::any_of(stages.begin(), stages.end(),
                    [&](const std::string& stage) { return store.ReadHeadKey(map.name, stage); });
    if (!info_.head_stages.empty() && !has_indexed_stage) continue;  // not indexed by design
    problems.push_back(
        {map.name, "", "", ShardName(shard) + " holds this map, which the index lacks" + kChanged});
  }
}

std::vector<VerifyProblem> VerifyCollectionIndex(
    const std::string& path, const std::vector<std::string>& file_input_stages,
    const std::function<void(int64_t, int64_t)>& progress, StructureCheck structure,
    ShardCheck shards) {
  CollectionIndexStore index(path);
  return index.VerifyCollection(file_input_stages, progress, structure, shards);
}

CollectionIndexInfo ReadCollectionIndexInfo(const std::string& path) {
  if (!IsCollectionIndex(path)) throw StoreError("'" + path + "' is not a collection index");
  return CollectionIndexStore(path).info();
}

}  // namespace areagraph

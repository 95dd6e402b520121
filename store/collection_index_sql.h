#pragma once

// The SQL of a collection index (collection_index.h): its schema, the copy of
// each shard store's rows (attached read-only as `shard`) and every lookup of
// the index store. The artifacts table is a store's without the payload and
// its codec; each map names the shard that holds its payloads.
namespace areagraph::collection_sql {

// One row: what the index holds. `head_stages` is empty when every artifact
// of every shard is indexed, else the newline-joined stages whose heads alone
// are (ag-store index --only final). `detail_stages` (newline-joined): the
// stages whose rows hold their payload's digest and size, summary and
// compute time; other rows leave them NULL and the shard answers. A store
// keeps those columns after the payload, so reading them walks the payload's
// pages: the index copies them only for the small final artifacts and stays
// quick however big the intermediate ones are.
inline constexpr char kCreateCollectionTable[] = R"sql(
CREATE TABLE collection (
  id INTEGER PRIMARY KEY CHECK (id = 1),
  head_stages TEXT NOT NULL,
  detail_stages TEXT NOT NULL,
  created_at TEXT NOT NULL)
)sql";

// Paths are relative to the index's folder, so that the folder can move.
inline constexpr char kCreateShardsTable[] = R"sql(
CREATE TABLE shards (
  id INTEGER PRIMARY KEY,
  path TEXT NOT NULL UNIQUE,
  maps INTEGER NOT NULL DEFAULT 0,
  artifacts INTEGER NOT NULL DEFAULT 0)
)sql";

inline constexpr char kCreateMapsTable[] = R"sql(
CREATE TABLE maps (
  id INTEGER PRIMARY KEY,
  name TEXT NOT NULL UNIQUE,
  source_path TEXT NOT NULL,
  source_digest TEXT NOT NULL,
  shard_id INTEGER NOT NULL REFERENCES shards(id))
)sql";

inline constexpr char kCreateArtifactsTable[] = R"sql(
CREATE TABLE artifacts (
  id INTEGER PRIMARY KEY,
  map_id INTEGER NOT NULL REFERENCES maps(id),
  stage TEXT NOT NULL,
  cache_key TEXT NOT NULL,
  input_keys TEXT NOT NULL,
  options TEXT NOT NULL,
  stage_version INTEGER NOT NULL,
  proto_type TEXT NOT NULL,
  created_at TEXT NOT NULL,
  payload_digest TEXT,
  payload_size INTEGER,
  elapsed_ms REAL,
  summary TEXT,
  UNIQUE (map_id, cache_key))
)sql";

inline constexpr char kCreateArtifactsByTimeIndex[] =
    "CREATE INDEX artifacts_by_map_and_time ON artifacts (map_id, created_at)";

inline constexpr char kCreateHeadsTable[] = R"sql(
CREATE TABLE heads (
  map_id INTEGER NOT NULL REFERENCES maps(id),
  stage TEXT NOT NULL,
  artifact_id INTEGER NOT NULL REFERENCES artifacts(id),
  PRIMARY KEY (map_id, stage))
)sql";

inline constexpr char kCreateVersionsTable[] = R"sql(
CREATE TABLE versions (
  map_id INTEGER NOT NULL REFERENCES maps(id),
  cache_key TEXT NOT NULL,
  stage TEXT NOT NULL,
  predecessor_key TEXT NOT NULL,
  number INTEGER NOT NULL,
  created_at TEXT NOT NULL,
  PRIMARY KEY (map_id, cache_key))
)sql";

inline constexpr char kCreateFailuresTable[] = R"sql(
CREATE TABLE failures (
  map_name TEXT PRIMARY KEY,
  stage TEXT NOT NULL,
  message TEXT NOT NULL,
  source_path TEXT NOT NULL,
  failed_at TEXT NOT NULL,
  shard_id INTEGER NOT NULL REFERENCES shards(id))
)sql";

inline constexpr char kWriteCollection[] =
    "INSERT INTO collection (id, head_stages, detail_stages, created_at)"
    " VALUES (1, ?1, ?2, strftime('%Y-%m-%dT%H:%M:%fZ', 'now'))";
inline constexpr char kReadCollection[] = "SELECT head_stages FROM collection WHERE id = 1";

// --- Indexing one shard (attached as `shard`) --------------------------------

inline constexpr char kAttachShard[] = "ATTACH DATABASE ?1 AS shard";
inline constexpr char kDetachShard[] = "DETACH DATABASE shard";
inline constexpr char kReadShardVersion[] = "PRAGMA shard.user_version";

inline constexpr char kInsertShard[] = "INSERT INTO shards (path) VALUES (?1) RETURNING id";

// A map the index already holds from another shard; a collection keeps each
// map in one shard.
inline constexpr char kFindSharedMap[] =
    "SELECT sm.name, sh.path FROM shard.maps sm JOIN main.maps m ON m.name = sm.name"
    " JOIN main.shards sh ON sh.id = m.shard_id ORDER BY sm.name LIMIT 1";

inline constexpr char kCopyMaps[] =
    "INSERT INTO main.maps (name, source_path, source_digest, shard_id)"
    " SELECT name, source_path, source_digest, ?1 FROM shard.maps ORDER BY name";

// `?2` is the JSON array of the stages whose heads alone are indexed, or
// NULL for every artifact; `?3` that of the stages whose rows get their
// details. The creation time comes from the shard's index by map and time,
// which holds it beside the row id: reading it from the row would walk the
// payload's pages.
#define AG_DETAIL(column) \
  "CASE WHEN a.stage IN (SELECT value FROM json_each(?3)) THEN " column " END"
inline constexpr char kCopyArtifacts[] =
    "INSERT INTO main.artifacts (map_id, stage, cache_key, input_keys, options, stage_version,"
    " proto_type, created_at, payload_digest, payload_size, elapsed_ms, summary)"
    " SELECT m.id, a.stage, a.cache_key, a.input_keys, a.options, a.stage_version, a.proto_type,"
    " (SELECT t.created_at FROM shard.artifacts t INDEXED BY artifacts_by_map_and_time"
    "  WHERE t.map_id = a.map_id AND t.rowid = a.id), " AG_DETAIL("a.payload_digest") ", "
    AG_DETAIL("a.payload_size") ", " AG_DETAIL("a.elapsed_ms") ", " AG_DETAIL("a.summary")
    " FROM shard.artifacts a"
    " JOIN shard.maps sm ON sm.id = a.map_id"
    " JOIN main.maps m ON m.name = sm.name AND m.shard_id = ?1"
    " WHERE ?2 IS NULL OR a.id IN (SELECT artifact_id FROM shard.heads"
    "                              WHERE stage IN (SELECT value FROM json_each(?2)))"
    " ORDER BY a.map_id, a.id";
#undef AG_DETAIL

inline constexpr char kCopyHeads[] = R"sql(
INSERT INTO main.heads (map_id, stage, artifact_id)
SELECT m.id, h.stage, ia.id
FROM shard.heads h
JOIN shard.artifacts a ON a.id = h.artifact_id
JOIN shard.maps sm ON sm.id = h.map_id
JOIN main.maps m ON m.name = sm.name AND m.shard_id = ?1
JOIN main.artifacts ia ON ia.map_id = m.id AND ia.cache_key = a.cache_key
WHERE a.stage = h.stage)sql";

inline constexpr char kCopyVersions[] = R"sql(
INSERT INTO main.versions (map_id, cache_key, stage, predecessor_key, number, created_at)
SELECT m.id, v.cache_key, v.stage, v.predecessor_key, v.number, v.created_at
FROM shard.versions v
JOIN shard.maps sm ON sm.id = v.map_id
JOIN main.maps m ON m.name = sm.name AND m.shard_id = ?1)sql";

// A failure that a later indexed head of its map outdates is left out, as a
// merge drops it (run after the heads are copied); the later of two failures
// of one name (overlapping shards) wins.
inline constexpr char kCopyFailures[] = R"sql(
INSERT INTO main.failures (map_name, stage, message, source_path, failed_at, shard_id)
SELECT f.map_name, f.stage, f.message, f.source_path, f.failed_at, ?1
FROM shard.failures f
WHERE NOT EXISTS (SELECT 1 FROM main.maps m JOIN main.heads h ON h.map_id = m.id
                  JOIN main.artifacts a ON a.id = h.artifact_id
                  WHERE m.name = f.map_name AND a.created_at > f.failed_at)
ON CONFLICT (map_name) DO UPDATE SET
  stage = excluded.stage, message = excluded.message, source_path = excluded.source_path,
  failed_at = excluded.failed_at, shard_id = excluded.shard_id
WHERE excluded.failed_at > failures.failed_at)sql";

// With only some stages' heads indexed, a map without any of them (it failed
// before) is left to the failures table.
inline constexpr char kDropMapsWithoutArtifacts[] =
    "DELETE FROM main.maps WHERE shard_id = ?1"
    " AND NOT EXISTS (SELECT 1 FROM main.artifacts a WHERE a.map_id = maps.id)";
inline constexpr char kDropVersionsOfDroppedMaps[] =
    "DELETE FROM main.versions WHERE map_id NOT IN (SELECT id FROM main.maps)";

inline constexpr char kCountShardRows[] =
    "UPDATE main.shards SET"
    " maps = (SELECT count(*) FROM main.maps WHERE shard_id = ?1),"
    " artifacts = (SELECT count(*) FROM main.artifacts a JOIN main.maps m ON m.id = a.map_id"
    "              WHERE m.shard_id = ?1)"
    " WHERE id = ?1 RETURNING maps, artifacts";

// --- Reading the index -------------------------------------------------------
// Maps, heads, versions and failures are read with the store's own
// statements (sqlite_store_sql.h, sqlite_versions_sql.h): the tables and
// columns they name are the same here.

inline constexpr char kReadShards[] = "SELECT id, path, maps, artifacts FROM shards ORDER BY id";

// Artifact rows as ReadIndexedRow (collection_index_store.cc) reads them;
// the last column says whether the row has its details.
#define AG_INDEX_ARTIFACT_COLUMNS                                                                 \
  "a.stage, a.cache_key, a.input_keys, a.options, a.stage_version, a.proto_type, "                \
  "coalesce(a.payload_digest, ''), a.created_at, coalesce(a.elapsed_ms, 0.0), "                   \
  "h.artifact_id IS NOT NULL, coalesce(a.summary, ''), coalesce(a.payload_size, 0), m.shard_id, " \
  "a.summary IS NOT NULL"
#define AG_INDEX_JOIN_HEAD \
  " LEFT JOIN heads h ON h.map_id = a.map_id AND h.stage = a.stage AND h.artifact_id = a.id"
inline constexpr char kReadArtifact[] =
    "SELECT " AG_INDEX_ARTIFACT_COLUMNS
    " FROM maps m JOIN artifacts a ON a.map_id = m.id" AG_INDEX_JOIN_HEAD
    " WHERE m.name = ?1 AND a.cache_key = ?2";
inline constexpr char kReadHead[] =
    "SELECT " AG_INDEX_ARTIFACT_COLUMNS
    " FROM maps m JOIN heads h ON h.map_id = m.id"
    " JOIN artifacts a ON a.id = h.artifact_id WHERE m.name = ?1 AND h.stage = ?2";
inline constexpr char kReadArtifactSummaries[] =
    "SELECT " AG_INDEX_ARTIFACT_COLUMNS
    " FROM maps m JOIN artifacts a ON a.map_id = m.id" AG_INDEX_JOIN_HEAD
    " WHERE m.name = ?1 ORDER BY a.created_at, a.id";
// Every indexed artifact of one shard's maps, for verify.
inline constexpr char kReadShardArtifacts[] =
    "SELECT m.name, " AG_INDEX_ARTIFACT_COLUMNS
    " FROM maps m JOIN artifacts a ON a.map_id = m.id" AG_INDEX_JOIN_HEAD
    " WHERE m.shard_id = ?1 ORDER BY m.name, a.id";
#undef AG_INDEX_ARTIFACT_COLUMNS
#undef AG_INDEX_JOIN_HEAD

inline constexpr char kCountArtifacts[] =
    "SELECT count(*) FROM maps m JOIN artifacts a ON a.map_id = m.id WHERE m.name = ?1";

// --- Verify ------------------------------------------------------------------

inline constexpr char kIntegrityCheck[] = "PRAGMA integrity_check";
inline constexpr char kQuickCheck[] = "PRAGMA quick_check";

// The heads of one shard's maps, to compare with the shard's own.
inline constexpr char kReadShardHeads[] =
    "SELECT m.name, h.stage, a.cache_key FROM maps m JOIN heads h ON h.map_id = m.id"
    " JOIN artifacts a ON a.id = h.artifact_id WHERE m.shard_id = ?1 ORDER BY m.name, h.stage";
inline constexpr char kReadShardMapNames[] =
    "SELECT name FROM maps WHERE shard_id = ?1 ORDER BY name";
// The stages whose heads the index holds: what a shard's heads are compared on.
inline constexpr char kReadHeadStages[] = "SELECT DISTINCT stage FROM heads ORDER BY stage";

// --- Keeping only some heads in a store (ag-store gc --keep final) -----------
// `?1` is the JSON array of the stages whose heads stay. Heads of the other
// stages go with their artifacts (ON DELETE CASCADE).

#define AG_NOT_KEPT                                 \
  " WHERE id NOT IN (SELECT artifact_id FROM heads" \
  "                  WHERE stage IN (SELECT value FROM json_each(?1)))"
inline constexpr char kCountNotKept[] =
    "SELECT count(*), coalesce(sum(payload_size), 0) FROM artifacts" AG_NOT_KEPT;
inline constexpr char kDeleteNotKept[] = "DELETE FROM artifacts" AG_NOT_KEPT;
#undef AG_NOT_KEPT
inline constexpr char kDeleteMapsWithoutArtifacts[] =
    "DELETE FROM maps WHERE NOT EXISTS (SELECT 1 FROM artifacts a WHERE a.map_id = maps.id)";

}  // namespace areagraph::collection_sql

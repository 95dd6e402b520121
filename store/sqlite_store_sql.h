#pragma once

// The SQL of the SQLite artifact store: its schema and every statement it
// prepares. Kept apart from the store class so that tests can ask SQLite for
// the query plans and check that lookups use the indexes.
namespace areagraph::store_sql {

// A map is a name plus the file its latest import came from.
inline constexpr char kCreateMapsTable[] = R"sql(
CREATE TABLE IF NOT EXISTS maps (
  id INTEGER PRIMARY KEY,
  name TEXT NOT NULL UNIQUE,
  source_path TEXT NOT NULL DEFAULT '',
  source_digest TEXT NOT NULL DEFAULT '')
)sql";

// One row per stage result; input_keys are newline-joined digests. The unique
// (map_id, cache_key) index serves cache lookups.
inline constexpr char kCreateArtifactsTable[] = R"sql(
CREATE TABLE IF NOT EXISTS artifacts (
  id INTEGER PRIMARY KEY,
  map_id INTEGER NOT NULL REFERENCES maps(id) ON DELETE CASCADE,
  stage TEXT NOT NULL,
  cache_key TEXT NOT NULL,
  input_keys TEXT NOT NULL,
  options TEXT NOT NULL,
  stage_version INTEGER NOT NULL,
  proto_type TEXT NOT NULL,
  payload BLOB NOT NULL,
  payload_digest TEXT NOT NULL,
  created_at TEXT NOT NULL,
  elapsed_ms REAL NOT NULL,
  summary TEXT NOT NULL DEFAULT '',
  payload_codec INTEGER NOT NULL DEFAULT 0,
  payload_size INTEGER NOT NULL DEFAULT 0,
  row_digest TEXT NOT NULL DEFAULT '',
  UNIQUE (map_id, cache_key))
)sql";

// Schema 3: the stage's one-line summary of each artifact, so that a cache hit
// can print it without reading the payload.
inline constexpr char kAddArtifactSummaryColumn[] =
    "ALTER TABLE artifacts ADD COLUMN summary TEXT NOT NULL DEFAULT ''";

// Schema 5: how each payload is kept (PayloadCodec; older rows stay as they
// were written, uncompressed) and the size of the decoded message, which
// summaries report without reading the payload.
inline constexpr char kAddPayloadCodecColumn[] =
    "ALTER TABLE artifacts ADD COLUMN payload_codec INTEGER NOT NULL DEFAULT 0";
inline constexpr char kAddPayloadSizeColumn[] =
    "ALTER TABLE artifacts ADD COLUMN payload_size INTEGER NOT NULL DEFAULT 0";
inline constexpr char kFillPayloadSizes[] = "UPDATE artifacts SET payload_size = length(payload)";

// Schema 6: the digest of the row's other columns (store/row_digest.h), so
// that damage to a key, an option or a summary is found like damage to a
// payload. ag_row_digest is the SQL form of ArtifactRowDigest, which every
// store connection registers; rows of an upgraded store get theirs here.
inline constexpr char kAddRowDigestColumn[] =
    "ALTER TABLE artifacts ADD COLUMN row_digest TEXT NOT NULL DEFAULT ''";
#define AG_ROW_DIGEST_OF(a, map_name, summary)                                                    \
  "ag_row_digest(" map_name ", " a ".stage, " a ".cache_key, " a ".input_keys, " a ".options, " a \
  ".stage_version, " a ".proto_type, " a ".payload_digest, " summary ", " a ".created_at)"
inline constexpr char kFillRowDigests[] = "UPDATE artifacts SET row_digest = " AG_ROW_DIGEST_OF(
    "artifacts", "(SELECT name FROM maps WHERE maps.id = artifacts.map_id)", "artifacts.summary");

// Listing a map's artifacts oldest first reads this index in order.
inline constexpr char kCreateArtifactsByTimeIndex[] = R"sql(
CREATE INDEX IF NOT EXISTS artifacts_by_map_and_time ON artifacts (map_id, created_at))sql";

// The current artifact of each (map, stage).
inline constexpr char kCreateHeadsTable[] = R"sql(
CREATE TABLE IF NOT EXISTS heads (
  map_id INTEGER NOT NULL REFERENCES maps(id) ON DELETE CASCADE,
  stage TEXT NOT NULL,
  artifact_id INTEGER NOT NULL REFERENCES artifacts(id) ON DELETE CASCADE,
  PRIMARY KEY (map_id, stage))
)sql";

// Deleting an artifact finds the heads that point at it without a scan.
inline constexpr char kCreateHeadsByArtifactIndex[] = R"sql(
CREATE INDEX IF NOT EXISTS heads_by_artifact ON heads (artifact_id))sql";

// Schema 2: the latest failure of each map, by name (a map whose import
// failed has no maps row). Plain CREATE: upgrading must fail, not skip, if
// something else already took the name.
inline constexpr char kCreateFailuresTable[] = R"sql(
CREATE TABLE failures (
  map_name TEXT PRIMARY KEY,
  stage TEXT NOT NULL,
  message TEXT NOT NULL,
  source_path TEXT NOT NULL DEFAULT '',
  failed_at TEXT NOT NULL)
)sql";

inline constexpr char kBegin[] = "BEGIN IMMEDIATE";
inline constexpr char kCommit[] = "COMMIT";
inline constexpr char kRollback[] = "ROLLBACK";

inline constexpr char kReadAllMaps[] =
    "SELECT id, name, source_path, source_digest FROM maps ORDER BY name";
inline constexpr char kReadMap[] =
    "SELECT id, name, source_path, source_digest FROM maps WHERE name = ?1";

// Artifact reads share their first columns; see ReadArtifactRow. Each comes
// in forms for older stores opened read-only, whose artifacts have no summary
// column (before schema 3), no payload codec (before schema 5) or no row
// digest (before schema 6).
#define AG_ARTIFACT_COLUMNS(summary, digest)                                       \
  "a.stage, a.cache_key, a.input_keys, a.options, a.stage_version, a.proto_type, " \
  "a.payload_digest, a.created_at, a.elapsed_ms, h.artifact_id IS NOT NULL, " summary ", " digest
#define AG_JOIN_HEAD_OF_ARTIFACT \
  " LEFT JOIN heads h ON h.map_id = a.map_id AND h.stage = a.stage AND h.artifact_id = a.id"
#define AG_READ_ARTIFACT(summary, codec, digest)                                       \
  "SELECT " AG_ARTIFACT_COLUMNS(                                                       \
      summary, digest) ", a.payload, " codec                                           \
                       " FROM maps m"                                                  \
                       " JOIN artifacts a ON a.map_id = m.id" AG_JOIN_HEAD_OF_ARTIFACT \
                       " WHERE m.name = ?1 AND a.cache_key = ?2"
#define AG_READ_HEAD(summary, codec, digest)                                                 \
  "SELECT " AG_ARTIFACT_COLUMNS(summary, digest) ", a.payload, " codec                       \
                                                 " FROM maps m"                              \
                                                 " JOIN heads h ON h.map_id = m.id"          \
                                                 " JOIN artifacts a ON a.id = h.artifact_id" \
                                                 " WHERE m.name = ?1 AND h.stage = ?2"
// Summaries carry the message's size: from payload_size (schema 5) or, in
// older stores, length(), which reads a BLOB's size without loading it.
#define AG_READ_ARTIFACT_SUMMARIES(summary, size, digest)                              \
  "SELECT " AG_ARTIFACT_COLUMNS(                                                       \
      summary, digest) ", " size                                                       \
                       " FROM maps m"                                                  \
                       " JOIN artifacts a ON a.map_id = m.id" AG_JOIN_HEAD_OF_ARTIFACT \
                       " WHERE m.name = ?1 ORDER BY a.created_at, a.id"
#define AG_READ_ARTIFACT_SUMMARY(summary, size, digest)                                \
  "SELECT " AG_ARTIFACT_COLUMNS(                                                       \
      summary, digest) ", " size                                                       \
                       " FROM maps m"                                                  \
                       " JOIN artifacts a ON a.map_id = m.id" AG_JOIN_HEAD_OF_ARTIFACT \
                       " WHERE m.name = ?1 AND a.cache_key = ?2"

inline constexpr char kReadArtifact[] =
    AG_READ_ARTIFACT("a.summary", "a.payload_codec", "a.row_digest");
inline constexpr char kReadHead[] = AG_READ_HEAD("a.summary", "a.payload_codec", "a.row_digest");
inline constexpr char kReadArtifactSummaries[] =
    AG_READ_ARTIFACT_SUMMARIES("a.summary", "a.payload_size", "a.row_digest");
inline constexpr char kReadArtifactSummary[] =
    AG_READ_ARTIFACT_SUMMARY("a.summary", "a.payload_size", "a.row_digest");
inline constexpr char kReadArtifactBeforeSchema6[] =
    AG_READ_ARTIFACT("a.summary", "a.payload_codec", "''");
inline constexpr char kReadHeadBeforeSchema6[] = AG_READ_HEAD("a.summary", "a.payload_codec", "''");
inline constexpr char kReadArtifactSummariesBeforeSchema6[] =
    AG_READ_ARTIFACT_SUMMARIES("a.summary", "a.payload_size", "''");
inline constexpr char kReadArtifactSummaryBeforeSchema6[] =
    AG_READ_ARTIFACT_SUMMARY("a.summary", "a.payload_size", "''");
inline constexpr char kReadArtifactBeforeSchema5[] = AG_READ_ARTIFACT("a.summary", "0", "''");
inline constexpr char kReadHeadBeforeSchema5[] = AG_READ_HEAD("a.summary", "0", "''");
inline constexpr char kReadArtifactSummariesBeforeSchema5[] =
    AG_READ_ARTIFACT_SUMMARIES("a.summary", "length(a.payload)", "''");
inline constexpr char kReadArtifactSummaryBeforeSchema5[] =
    AG_READ_ARTIFACT_SUMMARY("a.summary", "length(a.payload)", "''");
inline constexpr char kReadArtifactBeforeSchema3[] = AG_READ_ARTIFACT("''", "0", "''");
inline constexpr char kReadHeadBeforeSchema3[] = AG_READ_HEAD("''", "0", "''");
inline constexpr char kReadArtifactSummariesBeforeSchema3[] =
    AG_READ_ARTIFACT_SUMMARIES("''", "length(a.payload)", "''");
inline constexpr char kReadArtifactSummaryBeforeSchema3[] =
    AG_READ_ARTIFACT_SUMMARY("''", "length(a.payload)", "''");

#undef AG_ARTIFACT_COLUMNS
#undef AG_JOIN_HEAD_OF_ARTIFACT
#undef AG_READ_ARTIFACT
#undef AG_READ_HEAD
#undef AG_READ_ARTIFACT_SUMMARIES
#undef AG_READ_ARTIFACT_SUMMARY

// The parts of an artifact that UpdateHead needs.
inline constexpr char kReadArtifactRef[] =
    "SELECT a.id, a.map_id, a.stage FROM maps m JOIN artifacts a ON a.map_id = m.id"
    " WHERE m.name = ?1 AND a.cache_key = ?2";

// Creates the map, or updates its source only where the caller gave one.
inline constexpr char kUpsertMap[] = R"sql(
INSERT INTO maps (name, source_path, source_digest) VALUES (?1, coalesce(?2, ''), coalesce(?3, ''))
ON CONFLICT (name) DO UPDATE SET
  source_path = coalesce(?2, source_path), source_digest = coalesce(?3, source_digest))sql";

// Replaces a row with the same (map, key) in place, so its id and any head
// pointing at it stay valid.
inline constexpr char kUpsertArtifact[] = R"sql(
INSERT INTO artifacts (map_id, stage, cache_key, input_keys, options, stage_version, proto_type,
                       payload, payload_digest, created_at, elapsed_ms, summary, payload_codec,
                       payload_size, row_digest)
VALUES (?1, ?2, ?3, ?4, ?5, ?6, ?7, ?8, ?9, ?14, ?10, ?11, ?12, ?13, ?15)
ON CONFLICT (map_id, cache_key) DO UPDATE SET
  stage = excluded.stage, input_keys = excluded.input_keys, options = excluded.options,
  stage_version = excluded.stage_version, proto_type = excluded.proto_type,
  payload = excluded.payload, payload_digest = excluded.payload_digest,
  created_at = excluded.created_at, elapsed_ms = excluded.elapsed_ms,
  summary = excluded.summary, payload_codec = excluded.payload_codec,
  payload_size = excluded.payload_size, row_digest = excluded.row_digest)sql";

inline constexpr char kReadArtifactId[] =
    "SELECT id FROM artifacts WHERE map_id = ?1 AND cache_key = ?2";

// Cache checks that never touch a payload.
inline constexpr char kHasArtifact[] =
    "SELECT 1 FROM maps m JOIN artifacts a ON a.map_id = m.id"
    " WHERE m.name = ?1 AND a.cache_key = ?2";
inline constexpr char kReadHeadKey[] =
    "SELECT a.cache_key FROM maps m"
    " JOIN heads h ON h.map_id = m.id JOIN artifacts a ON a.id = h.artifact_id"
    " WHERE m.name = ?1 AND h.stage = ?2";

// Times as in artifacts.created_at, so the two compare as text.
inline constexpr char kRecordFailure[] = R"sql(
INSERT INTO failures (map_name, stage, message, source_path, failed_at)
VALUES (?1, ?2, ?3, ?4, strftime('%Y-%m-%dT%H:%M:%fZ', 'now'))
ON CONFLICT (map_name) DO UPDATE SET
  stage = excluded.stage, message = excluded.message, source_path = excluded.source_path,
  failed_at = excluded.failed_at)sql";
inline constexpr char kClearFailure[] = "DELETE FROM failures WHERE map_name = ?1";
inline constexpr char kReadFailures[] =
    "SELECT map_name, stage, message, source_path, failed_at FROM failures ORDER BY map_name";

inline constexpr char kWriteHead[] = R"sql(
INSERT INTO heads (map_id, stage, artifact_id) VALUES (?1, ?2, ?3)
ON CONFLICT (map_id, stage) DO UPDATE SET artifact_id = excluded.artifact_id)sql";

}  // namespace areagraph::store_sql

#pragma once

// The SQL of the store's maintenance (ag-store verify, gc and merge). Unlike
// the lookups in sqlite_store_sql.h these read whole tables on purpose; they
// run once per command, not once per stage.
#include "store/sqlite_store_sql.h"

namespace areagraph::store_sql {

// --- Verify ---------------------------------------------------------------

inline constexpr char kBeginRead[] = "BEGIN DEFERRED";
inline constexpr char kEndRead[] = "COMMIT";

inline constexpr char kCountArtifacts[] = "SELECT count(*) FROM artifacts";

// Every artifact with its payload, in storage order; the caller holds one
// row at a time. A row whose map is gone (hand-edited file) still shows up.
// Before schema 5 every payload is raw; before schema 6 rows have no digest
// (the columns it covers are then not read).
#define AG_VERIFY_ARTIFACTS(codec, row_columns)                                          \
  "SELECT a.id, a.map_id, m.id IS NOT NULL, coalesce(m.name, ''), a.stage, a.cache_key," \
  " a.input_keys, a.payload_digest, a.payload, " codec ", " row_columns                  \
  " FROM artifacts a LEFT JOIN maps m ON m.id = a.map_id ORDER BY a.id"
inline constexpr char kVerifyArtifacts[] =
    AG_VERIFY_ARTIFACTS("a.payload_codec",
                        "a.options, a.stage_version, a.proto_type, a.summary, a.created_at,"
                        " a.row_digest");
inline constexpr char kVerifyArtifactsBeforeSchema6[] =
    AG_VERIFY_ARTIFACTS("a.payload_codec", "'', 0, '', '', '', ''");
inline constexpr char kVerifyArtifactsBeforeSchema5[] =
    AG_VERIFY_ARTIFACTS("0", "'', 0, '', '', '', ''");
#undef AG_VERIFY_ARTIFACTS

// Heads that do not point at an artifact of their own map and stage.
inline constexpr char kFindBrokenHeads[] = R"sql(
SELECT coalesce(m.name, ''), h.stage, coalesce(a.cache_key, ''),
       CASE WHEN m.id IS NULL THEN 'head belongs to no map'
            WHEN a.id IS NULL THEN 'head points at no artifact'
            WHEN a.map_id != h.map_id THEN 'head points at an artifact of another map'
            ELSE 'head points at an artifact of stage ' || a.stage END
FROM heads h LEFT JOIN maps m ON m.id = h.map_id LEFT JOIN artifacts a ON a.id = h.artifact_id
WHERE m.id IS NULL OR a.id IS NULL OR a.map_id != h.map_id OR a.stage != h.stage
ORDER BY m.name, h.stage)sql";

// SQLite's own checks of one attached schema ("main" or "merge_source"): a
// row "ok", or up to 100 rows that each describe one problem.
inline constexpr char kIntegrityCheckOf[] = "PRAGMA %s.integrity_check";
inline constexpr char kQuickCheckOf[] = "PRAGMA %s.quick_check";

// --- Garbage collection ---------------------------------------------------

inline constexpr char kReadHeadArtifactIds[] = "SELECT artifact_id FROM heads";
inline constexpr char kReadArtifactInputs[] =
    "SELECT map_id, input_keys FROM artifacts WHERE id = ?1";
// The decoded sizes (gc needs a writable store, which has schema 5).
inline constexpr char kListArtifactSizes[] = "SELECT id, payload_size FROM artifacts";
inline constexpr char kDeleteArtifact[] = "DELETE FROM artifacts WHERE id = ?1";
inline constexpr char kDeleteEmptyMaps[] =
    "DELETE FROM maps WHERE NOT EXISTS (SELECT 1 FROM artifacts a WHERE a.map_id = maps.id)";

// --- Merge ----------------------------------------------------------------
// The other store is attached read-only as `merge_source`; rows are matched by
// map name and cache key, never by id, since ids differ between stores.

inline constexpr char kAttachMergeSource[] = "ATTACH DATABASE ?1 AS merge_source";
inline constexpr char kDetachMergeSource[] = "DETACH DATABASE merge_source";
inline constexpr char kReadMergeSourceVersion[] = "PRAGMA merge_source.user_version";

inline constexpr char kMergeMaps[] = R"sql(
INSERT INTO main.maps (name, source_path, source_digest)
SELECT name, source_path, source_digest FROM merge_source.maps WHERE true
ON CONFLICT (name) DO NOTHING)sql";

// What kMergeArtifacts will add: count and decoded payload bytes (run it
// first). A source before schema 5 holds raw payloads only.
#define AG_COUNT_NEW_ARTIFACTS(size)                   \
  "SELECT count(*), coalesce(sum(" size                \
  "), 0)"                                              \
  " FROM merge_source.artifacts sa"                    \
  " JOIN merge_source.maps sm ON sm.id = sa.map_id"    \
  " JOIN main.maps mm ON mm.name = sm.name"            \
  " WHERE NOT EXISTS (SELECT 1 FROM main.artifacts ma" \
  "                   WHERE ma.map_id = mm.id AND ma.cache_key = sa.cache_key)"
inline constexpr char kCountNewArtifacts[] = AG_COUNT_NEW_ARTIFACTS("sa.payload_size");
inline constexpr char kCountNewArtifactsBeforeSchema5[] =
    AG_COUNT_NEW_ARTIFACTS("length(sa.payload)");
#undef AG_COUNT_NEW_ARTIFACTS

// The first artifact that kMergeArtifacts would copy whose payload fails
// ag_payload_problem (a function the store registers: NULL when the payload
// decodes, matches its digest and is protobuf wire format, else the problem).
// Before schema 5 every payload is raw.
#define AG_FIND_DAMAGED_MERGE_PAYLOAD(codec)                                  \
  "SELECT sm.name, sa.stage, sa.cache_key,"                                   \
  " ag_payload_problem(sa.payload, " codec                                    \
  ", sa.payload_digest)"                                                      \
  " FROM merge_source.artifacts sa"                                           \
  " JOIN merge_source.maps sm ON sm.id = sa.map_id"                           \
  " WHERE NOT EXISTS ("                                                       \
  "   SELECT 1 FROM main.maps mm JOIN main.artifacts ma ON ma.map_id = mm.id" \
  "   WHERE mm.name = sm.name AND ma.cache_key = sa.cache_key)"               \
  " AND ag_payload_problem(sa.payload, " codec                                \
  ", sa.payload_digest) IS NOT NULL"                                          \
  " ORDER BY sa.id LIMIT 1"
inline constexpr char kFindDamagedMergePayload[] =
    AG_FIND_DAMAGED_MERGE_PAYLOAD("sa.payload_codec");
inline constexpr char kFindDamagedMergePayloadBeforeSchema5[] = AG_FIND_DAMAGED_MERGE_PAYLOAD("0");
#undef AG_FIND_DAMAGED_MERGE_PAYLOAD

// The first artifact row of the source whose columns do not match its row
// digest (schema 6): a damaged key, input, option, summary or time.
inline constexpr char kFindDamagedMergeRow[] =
    "SELECT sm.name, sa.stage, sa.cache_key FROM merge_source.artifacts sa"
    " JOIN merge_source.maps sm ON sm.id = sa.map_id"
    " WHERE sa.row_digest != " AG_ROW_DIGEST_OF("sa", "sm.name",
                                                "sa.summary") " ORDER BY sa.id LIMIT 1";

// Copies rows verbatim, creation time, payload codec and row digest
// included; an existing key is kept. A source older than schema 3 has no
// summary lines, one older than schema 5 only uncompressed payloads, one
// older than 6 no row digests (they are made here).
#define AG_MERGE_ARTIFACTS(summary, codec, size, digest)                                      \
  "INSERT INTO main.artifacts (map_id, stage, cache_key, input_keys, options, stage_version," \
  " proto_type, payload, payload_digest, created_at, elapsed_ms, summary, payload_codec,"     \
  " payload_size, row_digest)"                                                                \
  " SELECT mm.id, sa.stage, sa.cache_key, sa.input_keys, sa.options, sa.stage_version,"       \
  " sa.proto_type, sa.payload, sa.payload_digest, sa.created_at, sa.elapsed_ms, " summary     \
  ", " codec ", " size ", " digest                                                            \
  " FROM merge_source.artifacts sa"                                                           \
  " JOIN merge_source.maps sm ON sm.id = sa.map_id"                                           \
  " JOIN main.maps mm ON mm.name = sm.name"                                                   \
  " WHERE true"                                                                               \
  " ON CONFLICT (map_id, cache_key) DO NOTHING"
inline constexpr char kMergeArtifacts[] =
    AG_MERGE_ARTIFACTS("sa.summary", "sa.payload_codec", "sa.payload_size", "sa.row_digest");
inline constexpr char kMergeArtifactsBeforeSchema6[] =
    AG_MERGE_ARTIFACTS("sa.summary", "sa.payload_codec", "sa.payload_size",
                       AG_ROW_DIGEST_OF("sa", "sm.name", "sa.summary"));
inline constexpr char kMergeArtifactsBeforeSchema5[] = AG_MERGE_ARTIFACTS(
    "sa.summary", "0", "length(sa.payload)", AG_ROW_DIGEST_OF("sa", "sm.name", "sa.summary"));
inline constexpr char kMergeArtifactsBeforeSchema3[] =
    AG_MERGE_ARTIFACTS("''", "0", "length(sa.payload)", AG_ROW_DIGEST_OF("sa", "sm.name", "''"));
#undef AG_MERGE_ARTIFACTS

// The source's heads that win, as ids of this store: where this store has no
// head for (map, stage), or its head artifact was created earlier than the
// source's. Kept in a temporary table for the map-source update and the
// head upsert below.
inline constexpr char kCreateWinningHeads[] = R"sql(
CREATE TEMP TABLE merge_winning_heads (map_id INTEGER, stage TEXT, artifact_id INTEGER))sql";
inline constexpr char kFindWinningHeads[] = R"sql(
INSERT INTO temp.merge_winning_heads (map_id, stage, artifact_id)
SELECT mm.id, sh.stage, ma.id
FROM merge_source.heads sh
JOIN merge_source.maps sm ON sm.id = sh.map_id
JOIN merge_source.artifacts sa ON sa.id = sh.artifact_id
JOIN main.maps mm ON mm.name = sm.name
JOIN main.artifacts ma ON ma.map_id = mm.id AND ma.cache_key = sa.cache_key
LEFT JOIN main.heads mh ON mh.map_id = mm.id AND mh.stage = sh.stage
LEFT JOIN main.artifacts cur ON cur.id = mh.artifact_id
WHERE cur.id IS NULL OR (sa.created_at > cur.created_at AND cur.id != ma.id))sql";
inline constexpr char kDropWinningHeads[] = "DROP TABLE temp.merge_winning_heads";

// A map's source is the file of its import head, so it moves with that head.
inline constexpr char kMergeMapSources[] = R"sql(
UPDATE main.maps SET
  source_path = (SELECT sm.source_path FROM merge_source.maps sm WHERE sm.name = maps.name),
  source_digest = (SELECT sm.source_digest FROM merge_source.maps sm WHERE sm.name = maps.name)
WHERE id IN (SELECT map_id FROM temp.merge_winning_heads WHERE stage = 'import'))sql";

inline constexpr char kMergeHeads[] = R"sql(
INSERT INTO main.heads (map_id, stage, artifact_id)
SELECT map_id, stage, artifact_id FROM temp.merge_winning_heads WHERE true
ON CONFLICT (map_id, stage) DO UPDATE SET artifact_id = excluded.artifact_id)sql";

// True when map `name` has a head artifact created after `time`.
#define AG_HEAD_NEWER_THAN(name, time)                                     \
  "EXISTS (SELECT 1 FROM main.maps m JOIN main.heads h ON h.map_id = m.id" \
  " JOIN main.artifacts a ON a.id = h.artifact_id WHERE m.name = " name    \
  " AND a.created_at > " time ")"

// Run after the heads are merged: a failure older than a head is stale.
inline constexpr char kMergeFailures[] =
    "INSERT INTO main.failures (map_name, stage, message, source_path, failed_at)"
    " SELECT sf.map_name, sf.stage, sf.message, sf.source_path, sf.failed_at"
    " FROM merge_source.failures sf"
    " WHERE NOT EXISTS (SELECT 1 FROM main.failures f"
    "                   WHERE f.map_name = sf.map_name AND f.failed_at >= sf.failed_at)"
    " AND NOT " AG_HEAD_NEWER_THAN("sf.map_name", "sf.failed_at")
    " ON CONFLICT (map_name) DO UPDATE SET stage = excluded.stage, message = excluded.message,"
    " source_path = excluded.source_path, failed_at = excluded.failed_at";
// This store's own failures of the merged maps that a merged head outdates.
inline constexpr char kDropOutdatedFailures[] =
    "DELETE FROM main.failures"
    " WHERE map_name IN (SELECT name FROM merge_source.maps)"
    " AND " AG_HEAD_NEWER_THAN("failures.map_name", "failures.failed_at");

#undef AG_HEAD_NEWER_THAN

}  // namespace areagraph::store_sql

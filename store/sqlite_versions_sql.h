#pragma once

// The SQL of each map's history of versions (schema 4): one row per artifact
// of a stage that reads its previous version (match), with the key of that
// predecessor. Rows name artifacts by key, not by id, so that they outlive
// the artifacts that gc drops: the history stays readable.
namespace areagraph::store_sql {

// Plain CREATE: upgrading must fail, not skip, if something else took the name.
inline constexpr char kCreateVersionsTable[] = R"sql(
CREATE TABLE versions (
  map_id INTEGER NOT NULL REFERENCES maps(id) ON DELETE CASCADE,
  cache_key TEXT NOT NULL,
  stage TEXT NOT NULL,
  predecessor_key TEXT NOT NULL DEFAULT '',
  number INTEGER NOT NULL,
  created_at TEXT NOT NULL,
  PRIMARY KEY (map_id, cache_key))
)sql";

// A version is recorded once; recomputing it (--force) keeps its first row.
// Times as in artifacts.created_at.
inline constexpr char kInsertVersion[] = R"sql(
INSERT INTO versions (map_id, cache_key, stage, predecessor_key, number, created_at)
VALUES (?1, ?2, ?3, ?4, ?5, strftime('%Y-%m-%dT%H:%M:%fZ', 'now'))
ON CONFLICT (map_id, cache_key) DO NOTHING)sql";

// Each row with whether its artifact is still stored and is its stage's head.
#define AG_READ_VERSIONS(where)                                                               \
  "SELECT v.cache_key, v.predecessor_key, v.number, v.stage, v.created_at, a.id IS NOT NULL," \
  " h.artifact_id IS NOT NULL FROM maps m JOIN versions v ON v.map_id = m.id"                 \
  " LEFT JOIN artifacts a ON a.map_id = v.map_id AND a.cache_key = v.cache_key"               \
  " LEFT JOIN heads h ON h.map_id = v.map_id AND h.stage = v.stage AND h.artifact_id = a.id"  \
  " WHERE m.name = ?1" where
inline constexpr char kReadVersions[] = AG_READ_VERSIONS(" ORDER BY v.created_at, v.number");
inline constexpr char kReadVersion[] = AG_READ_VERSIONS(" AND v.cache_key = ?2");
#undef AG_READ_VERSIONS

// ag-store merge: the source's rows, matched by map name and key (see
// sqlite_store_maintenance_sql.h); a row both stores hold keeps this one's.
inline constexpr char kMergeVersions[] = R"sql(
INSERT INTO main.versions (map_id, cache_key, stage, predecessor_key, number, created_at)
SELECT mm.id, sv.cache_key, sv.stage, sv.predecessor_key, sv.number, sv.created_at
FROM merge_source.versions sv
JOIN merge_source.maps sm ON sm.id = sv.map_id
JOIN main.maps mm ON mm.name = sm.name
WHERE true
ON CONFLICT (map_id, cache_key) DO NOTHING)sql";

}  // namespace areagraph::store_sql

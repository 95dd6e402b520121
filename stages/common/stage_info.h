#pragma once

#include <google/protobuf/message.h>

#include <optional>
#include <string>
#include <vector>

#include "store/artifact_store.h"

namespace areagraph {

// A stage's identity in cache keys. Bump `version` whenever the stage's
// output changes for the same input, so that cached results are recomputed.
// Renaming or folding options needs no bump: the canonical options in the
// key change by themselves (clean's, cut's and match's switches becoming
// skip_passes and cut's W switch folding into cut.room_width_m left every
// artifact byte as it was with the defaults and with paper.pbtxt, only
// match's segmentation_options_digest follows the new options).
struct StageInfo {
  const char* name;
  int version;
};

inline constexpr StageInfo kImportStage{"import", 1};
// clean 2: outlier threshold for k + 1 points; 3: unknown islands become free.
// clean 4: furniture removal keeps pieces of wall standing between two doors
// (clean pass KEEP_WALL_PIECES; scans whose short wall pieces looked like furniture).
// clean 5: the CleanedMap carries clean.robot_width_m, which merge reads (robot_width_m).
// clean 6: the typical wall leaves out ridges over kMaxWallThicknessM, 0.6 m (was 1 m), the
// thickest wall end cut allows beside a door: one greatest wall thickness.
inline constexpr StageInfo kCleanStage{"clean", 6};
// voronoi 2: edges in face order.
// voronoi 3: the diagram as packed arrays (format 2), cheaper to write and read; same numbers.
inline constexpr StageInfo kVoronoiStage{"voronoi", 3};
// prune 2: every part of the map above prune.min_component_m2 is kept, not only the biggest.
// prune 3: long graphs beside a longer one in their part are kept too (prune.keep_groups_above_m;
// a room behind a gap the graph does not pass got no area).
// prune 4: edge polygons, boundaries and part outlines as packed rings (TopologyGraph format 2),
// a third of the memory of Point2 messages; same numbers.
// prune 5: the TopologyGraph carries prune.min_clearance_m, which merge reads (min_clearance_m).
inline constexpr StageInfo kPruneStage{"prune", 5};
// cut 2: stores the W used (RoomWidthEstimate), and can estimate it (auto).
// cut 3: obstacle islands (furniture) do not stop the room disk (cut.room_island_max_m).
// cut 4: room detection inside every part's boundary; parts carried to merge.
// cut 5: doors with wall jambs closed for the room disk (cut.close_wall_doors).
// cut 6: gaps beside thin wall ends closed too (cut.close_wall_gaps_max_m).
// cut 7: passages on doors and wall gaps closed on purpose are marked (closed_by_cut).
// cut 8: island_end_on_face on (face's middle only); wall gaps up to 3.5 m, short wall tips.
// cut 9: a tip shorter than W behind a door or wall gap the cut closed keeps its own room
// (cut.keep_closed_room_tips; closets behind doors). Also in cut 9: a room's edge running on into a
// narrow tail (a corridor wider than W but at most half as wide as the room) is cut where the tail
// begins (cut.cut_narrow_tails; side corridors running on from a hall).
// cut 10: a block continued end-on at one end is a wall piece only when its other end faces an
// obstacle within a door's width (cut.island_wall_piece_both_ends; rows of furniture).
// cut 11: past a jamb, free cells the door's free space cannot reach count as wall (outside drawn
// free, hollow blocks; cut.jamb_wall_behind_line).
// cut 12: edge polygons and room shapes as packed rings (CutGraph format 2, as prune 4).
// cut 13: the openings (narrowings, wall gaps, mouths) and their decisions kept in the CutGraph.
// cut 14: the CutGraph carries the TopologyGraph's min_clearance_m on to merge.
// cut 15: a block is continued end-on by a wall running on for kJambRunM (0.3 m, was 0.4 m).
// Also in cut 15: the narrowest corridor is the narrowest stretch (no 5 m in all).
// Also in cut 15: a wall gap's thin wall end runs on for kJambRunM only (no quarter of the gap).
// Also in cut 15: islands are as thick as merge's, kMinFurnitureThicknessM (0.3 m, was 0.8 m).
// Also in cut 15: a narrow tail is kCorridorWidthRatio (1.3, was 2) times narrower than its room.
// cut 16: with an estimated W, a space the room disk finds no room in is one room when the disk of
// the typical door (median door + 0.1 m) finds it holding no room of W's (pass SMALL_ROOM_DISK).
// cut 17: the CutGraph carries cut.islands.max_length_m on to merge (its furniture islands).
// cut 18: the narrowest door (wall gaps, mouths, the least W) is clean.robot_width_m from the
// CleanedMap (was kMinGapM, 0.5 m, the default: a different body width now moves cut).
// cut 19: a block is continued end-on by an obstacle at most kCorridorWidthRatio (1.3, was 1.5)
// times as wide: the shape model's "about as wide".
// cut 20: a narrow tail begins within SteadyWidthSpreadM (0.1 m or 10 %) of its median width, the
// width estimate's steady corridor width (was a factor of 1.15 of its median clearance).
// cut 21: one greatest wall thickness, kMaxWallThicknessM (0.6 m): a door's wall end as before
// (was kMaxTipWallM), the typical wall, for the islands' least thickness, leaves out thicker
// ridges (was 1 m).
inline constexpr StageInfo kCutStage{"cut", 21};
// merge 2: growth stops at narrow gaps, freed cells stay out, small areas fold.
// merge 3: corridor pieces can be joined (merge.join_corridor_pieces).
// merge 4: open bays fold into their room (merge.fold_open_bays).
// merge 5: polygons are a simplified planar partition, passages lie on shared borders.
// merge 6: rooms meeting without a narrowing join; door stubs no longer stop corridor joining.
// merge 7: areas in every part's boundary, components and dropped parts counted.
// merge 8: areas join at furniture gaps; corridor-shaped rooms are labelled corridors.
// merge 9: room and furniture-gap joining keep doors the cut closed (merge.keep_closed_doors).
// merge 10: desks drawn as closed outlines are islands (merge.fill_furniture_outlines_m).
// merge 11: bins and cabinets against thin walls are islands (merge.wall_furniture_islands), and
// corridor-shaped rooms join at such gaps whatever their size, also at closed cuts
// (merge.join_corridor_clutter; bins against corridor walls).
// Also in merge 11: small rooms opening widely into a corridor and another area
// are corridor pieces and fold into it (merge.fold_corridor_pieces_below_m2).
// merge 12: two areas meeting at three or more vertices, one of them a gap too narrow for a door,
// are one area (merge.join_porous_borders_gap_m; clutter in a room); and pieces of one
// corridor that the room disk split (an automatic W near the corridor's width) join where they
// meet straight on without a narrowing (merge.join_split_corridors; generated floors against a
// fixed W = 1.25 m).
// merge 13: furniture islands are at most 5 times as long as wide (a thick piece of wall between
// two doors is no desk; merge.furniture_max_elongation). Also in merge 13:
// corridor pieces join at a narrowing with a flat wall on one side
// (merge.join_one_sided_narrowings), count as long and narrow as a chain
// (merge.join_split_corridor_chains), and dead-end branches that do not narrow at their mouth join
// their corridor (merge.join_corridor_stems); generated tuning floors lost to a fixed W = 1.25 m.
// merge 14: a small room behind a closed door, one area with walls seen, is not folded away
// (merge.keep_small_closed_rooms, with cut 9).
// Also in merge 14: corridor stem joining joins stems only into corridors at most 4 m wide
// (merge.corridor_stems_max_width_m), so a hall does not take back the tails cut 9 cut off.
// merge 15: a small closed room whose jambs are both thick obstacles (a pocket between cabinets) is
// folded after all (merge.closed_room_pocket_jamb_m).
// merge 16: one shape model and one definition of a corridor for every pass and the areas' kinds,
// the passes in one table (merge.skip_passes), corridor clutter joining removed.
// merge 17: every border between two areas that a body fits across is a passage, also without a
// graph vertex there (merge.open_border_clearance_m); labels unchanged.
// merge 18: a pocket's jamb is measured up to merge.small_closed_rooms.pocket_jamb_m, no longer
// taken as endless past 1.5 m (the same areas for values up to 1.5 m).
// merge 19: areas join across a stack of rows of long free-standing blocks (seats, shelves).
// merge 20: an area's kind is its shape's alone: a room unless shaped like a corridor (a way
// through is a corridor, one exit a dead end), whether the room disk fits or not; labels unchanged.
// merge 21: fewer constants: rows of a stack need not run parallel (their overlap decides), a
// corridor stem has no least width of its own, a row no greatest length; a bay's mouth is measured
// within ag-cut's door reach (1.5 m) instead of two of the bay's widths.
// merge 22: the AreaGraph carries the CleanedMap's robot_width_m on to match.
// merge 23: a corridor narrows below its median width over kCorridorWidthRatio (1 / 1.3 = 0.77) in
// corridor piece joining (was 0.75), split corridor and stem joining (was 0.8). Also in merge 23:
// rows need no least solidity, a one-sided narrowing no least share of the corridor's width.
// merge 24: the typical wall, for furniture islands, leaves out ridges over kMaxWallThicknessM
// (0.6 m, was 1 m), cut's thickest wall end: one greatest wall thickness.
// merge 25: two rows stand side by side in a stack when they overlap at all along the axis (no
// least share of the shorter one).
// merge 26: split corridor pieces need not run along the line between them (their centroids'
// angle decides), and a corridor stem need not run straight (kStraightAxisRatio removed).
// merge 27: a pocket's jambs are at least 0.45 m thick (merge.small_closed_rooms.pocket_jamb_m,
// was 0.6), the value tools/tune.sh chose on the tuning split.
inline constexpr StageInfo kMergeStage{"merge", 27};
// match 2: new pieces that noise split off an area fold back (match.fold_fragments_below_m2).
// match 3: merge's joins of two previous areas are cut apart again (match.split_joins_below_m2).
// match 4: joins cut across passages, at half inside, along moved walls, in rounds.
// match 5: joins also cut where the id moved to a leftover, without a passage, along pinched
// outlines, and with a 0.5 m least opening (ids lost to scan noise alone).
// match 6: join undoing runs rounds until one cuts nothing, not up to match.split_joins_rounds.
inline constexpr StageInfo kMatchStage{"match", 6};

// Whether two StageInfos name the same stage.
inline bool SameStage(const StageInfo& a, const StageInfo& b) {
  return std::string(a.name) == b.name;
}

// The format_version that this build writes into each artifact message.
// Bump one when the meaning of its fields changes, so that older builds
// refuse the artifact (ParseArtifact) instead of misreading it.
inline constexpr uint32_t kGridMapFormatVersion = 1;
inline constexpr uint32_t kCleanedMapFormatVersion = 1;
// VoronoiDiagram 2: parallel packed arrays instead of a message per site, vertex and edge.
inline constexpr uint32_t kVoronoiDiagramFormatVersion = 2;
// TopologyGraph and CutGraph 2: rings packed (Ring.xy, proto/geometry.proto); format 1 rings,
// Point2 messages, still read.
inline constexpr uint32_t kTopologyGraphFormatVersion = 2;
inline constexpr uint32_t kCutGraphFormatVersion = 2;
inline constexpr uint32_t kAreaGraphFormatVersion = 1;

// What one stage run did.
struct StageRun {
  std::string cache_key;
  bool cache_hit = false;
  // Time spent computing, or 0 on a hit.
  double elapsed_ms = 0;
  // The artifact's one-line summary (StageDefinition::summarize).
  std::string summary;
};

// Where a stage's inputs came from: the digests that enter its cache key.
struct StageInputs {
  std::vector<std::string> digests;
  // Set for a stage that reads its previous version (match): that version's
  // key (empty for the first), which enters the cache key after `digests`,
  // and the number this run's version gets.
  std::optional<VersionLink> version;
  // Set by ag-import only: recorded on the map row.
  std::optional<std::string> source_path;
  std::optional<std::string> source_digest;
};

// The cache key of a stage run: what RunCachedStage looks up and stores.
std::string StageCacheKey(const StageInfo& stage, const google::protobuf::Message& options,
                          const std::vector<std::string>& input_keys);

}  // namespace areagraph

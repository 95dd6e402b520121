# shellcheck shell=bash
# Sourced by the quality scripts that score whole sets (bench-ablation.sh,
# tune.sh): which maps each set holds and how ag-eval scores them. Expects
# DATA (the data folder, ../shared/data), BIN (the binaries) and OUT set.

# set_manifest SET: writes $OUT/SET.tsv (path, name) and $OUT/SET.eval (the
# ground truth folder, then ag-eval's flags for the set). SET is areagraph,
# robotmap, bormann-plain, bormann-furnished or a part of
# `ag-make-benchmark` (tuning, held-out, public-tuning, public-held-out),
# which is generated into $OUT/generated-SET.
set_manifest() {
  local set=$1 m=$OUT/$1.tsv suffix='' image gt base
  local ag=$DATA/areagraph rm=$DATA/maoris/RobotMap bm=$DATA/bormann
  printf 'path\tname\n' >"$m"
  case $set in
    areagraph)
      for image in "$ag"/input/*.png; do printf '%s\t%s\n' "$(realpath "$image")" "$(basename "$image" .png)"; done >>"$m"
      echo "$ag/GT" >"$OUT/$set.eval" ;;
    robotmap)
      for image in "$rm"/Maps/*.png; do printf '%s\t%s\n' "$(realpath "$image")" "$(basename "$image" .png)"; done >>"$m"
      echo "$rm/GT --gt-style maoris-lines" >"$OUT/$set.eval" ;;
    bormann-plain|bormann-furnished)
      [ "$set" = bormann-furnished ] && suffix=_furnitures
      for gt in "$bm"/*_gt_segmentation.png; do
        base=$(basename "$gt" _gt_segmentation.png)
        [ -e "$bm/$base$suffix.png" ] && printf '%s\t%s\n' "$(realpath "$bm/$base$suffix.png")" "$base"
      done >>"$m"
      echo "$bm --gt-suffix _gt_segmentation --gt-style lines --scale-result" >"$OUT/$set.eval" ;;
    tuning|held-out|public-tuning|public-held-out)
      rm -rf "$OUT/generated-$set"
      "$BIN/ag-make-benchmark" --part "$set" "$OUT/generated-$set" >/dev/null
      for image in "$OUT/generated-$set"/maps/*.png; do
        printf '%s\t%s\n' "$(realpath "$image")" "$(basename "$image" .png)"
      done >>"$m"
      echo "$OUT/generated-$set/gt --gt-style labels" >"$OUT/$set.eval" ;;
    *) echo "$(basename "$0" .sh): unknown set '$set'" >&2; exit 2 ;;
  esac
}

# score_part SET DIR BIN [ag-run flags]: runs the set's maps (set_manifest
# SET first) with BIN's ag-run in a new store DIR.db, exports their labels to
# DIR/<map>.png and prints the set's mean MCC (ag-eval, maoris). The store is
# new each time because match reads a map's earlier Area Graph: a store that
# holds another run's results scores differently. With SEED_STORE set, the
# store starts as a copy of that one (see upstream_store). Expects JOBS set.
score_part() {
  local set=$1 dir=$2 bin=$3 gt flags
  shift 3
  local store=$dir.db
  rm -rf "$dir" "$store" "$store-wal" "$store-shm"
  mkdir -p "$dir"
  [ -z "${SEED_STORE:-}" ] || cp "$SEED_STORE" "$store"
  "$bin/ag-run" --store "$store" --jobs "$JOBS" "$@" "$OUT/$set.tsv" >"$dir.log" 2>&1 ||
    echo "$(basename "$0" .sh): $set: $(grep -c failed "$dir.log") failed (see $dir.log)" >&2
  # Tried twice before a map counts as missing (ag-export names it).
  "$bin/ag-export" --store "$store" --all --format labels --out "$dir" >/dev/null 2>&1 ||
    "$bin/ag-export" --store "$store" --all --format labels --out "$dir" >/dev/null \
      2>"$dir.export-errors" ||
    echo "$(basename "$0" .sh): $set: $(cat "$dir.export-errors")" >&2
  rm -f "$store" "$store-wal" "$store-shm"
  read -r gt flags <"$OUT/$set.eval"
  # shellcheck disable=SC2086 # flags holds several words
  { "$bin/ag-eval" --dataset --results "$dir" --gt "$gt" --mcc-variant maoris $flags 2>/dev/null ||
      true; } | awk -F'|' '$2 ~ /mean/ { gsub(/[ *]/, "", $3); print $3 }'
}

# upstream_store SET BIN -> $OUT/SET-upstream.db, made once: the set's maps
# through import, clean, voronoi and prune only (no Area Graph, so nothing for
# match to read). A run seeded with it (SEED_STORE) computes only cut, merge
# and match, and scores as a new store does when its binaries and options
# compute the same first four stages.
upstream_store() {
  local set=$1 bin=$2 stage store=$OUT/$1-upstream.db
  if [ ! -e "$store" ]; then
    rm -f "$store.part" "$store.part-wal" "$store.part-shm"
    for stage in import clean voronoi prune; do
      "$bin/ag-run" --store "$store.part" --jobs "$JOBS" --only "$stage" "$OUT/$set.tsv" \
        >/dev/null 2>&1 || true
    done
    mv "$store.part" "$store"
  fi
  echo "$store"
}

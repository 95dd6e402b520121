# shellcheck shell=bash disable=SC2154
# Sourced by tools/bench-speed.sh: the tables that grow one map against the
# floor, each in one run of the script. Expects `bin`, `work`,
# `runs`, `floor_repeat`, `data`, `tiles`, `clutter_sizes` and `notes` set. Every timed command runs under /usr/bin/time, which
# gives its wall time, CPU time (user + system) and peak resident memory (the
# largest of the process and the children it waited for).

# timed_run OUT COMMAND...: runs COMMAND quietly; appends "wall cpu rss_kb"
# to OUT. A failure becomes a note and appends nothing.
timed_run() {
  local out=$1 status=0
  shift
  /usr/bin/time -f '%e %U %S %M' -o "$work/time.txt" "$@" >"$work/series.log" 2>&1 || status=$?
  if [ "$status" -ne 0 ]; then
    notes+=("$(basename "$1") failed (exit $status): $(tail -1 "$work/series.log")")
    return 1
  fi
  awk '{ printf "%s %.3f %s\n", $1, $2 + $3, $4 }' "$work/time.txt" >>"$out"
}

# The median of the numbers on stdin, one a line ("" for none).
stdin_median() { sort -g | awk '{ v[NR] = $1 } END { if (NR) print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2 }'; }

# column N FILE: the median of column N of FILE.
column() { awk -v c="$1" '{ print $c }' "$2" | stdin_median; }

# The floor of one image in one process: median ms, and that process's peak
# resident memory in MB.
floor_of() {
  local map=$1
  /usr/bin/time -f '%M' -o "$work/floor_rss.txt" \
    "$bin/ag-bench-floor" --repeat "$floor_repeat" "$map" >"$work/floor_one.txt"
  floor_ms=$(awk '$1 != "map" && $1 != "total" { print $NF }' "$work/floor_one.txt")
  floor_mb=$(awk '{ printf "%.0f", $1 / 1024 }' "$work/floor_rss.txt")
}

# The same floor with glibc's huge-page tunable, which ag-run sets for itself
# on maps over 5 Mpx (common/process_setup/huge_page_restart.h): sets floor_hp_ms. The
# tables' "× floor" keeps the floor as the targets define it (glibc's defaults);
# this one shows how much of ag-run's gain on big maps the floor would get too.
floor_with_huge_pages_of() {
  floor_hp_ms=$(GLIBC_TUNABLES=glibc.malloc.hugetlb=1 \
    "$bin/ag-bench-floor" --repeat "$floor_repeat" "$1" |
    awk '$1 != "map" && $1 != "total" { print $NF }')
}

# ag-run --jobs 1 on MAP from a new store each time, --runs times; sets
# run_wall, run_cpu (medians, s) and run_mb (median peak MB), and leaves the
# last store in $work/series.db.
run_cold() {
  local map=$1
  : >"$work/run.txt"
  for ((run = 1; run <= runs; ++run)); do
    rm -f "$work"/series.db*
    timed_run "$work/run.txt" "$bin/ag-run" --jobs 1 --store "$work/series.db" "$map" || true
  done
  run_wall=$(column 1 "$work/run.txt")
  run_cpu=$(column 2 "$work/run.txt")
  run_mb=$(awk '{ print $3 / 1024 }' "$work/run.txt" | stdin_median)
}

ratio() { awk -v a="$1" -v b="$2" 'BEGIN { if (b > 0 && a != "") printf "%.1f", a / b; else printf "–" }'; }

# The tiling scale series: lab_a repeated N x N (ag-bench-tile).
scale_table() {
  local source="$data/lab_a.png" n map mpx
  [ -f "$source" ] || { notes+=("no $source: the scale series did not run"); return; }
  echo "#### Scale: lab_a tiled N x N into one connected map (ag-bench-tile), ag-run --jobs 1"
  echo
  echo -n "| tiles | Mpx | floor s | floor MB | ag-run s | CPU s | × floor | s per Mpx | CPU s per Mpx"
  echo " | peak MB | MB × floor | floor s, huge pages | × that |"
  echo "|---|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|"
  for n in $tiles; do
    map="$work/lab_a_${n}x${n}.png"
    "$bin/ag-bench-tile" --tiles "$n" "$source" "$map" >/dev/null
    echo "bench-speed: scale $n x $n" >&2
    floor_of "$map"
    floor_with_huge_pages_of "$map"
    run_cold "$map"
    mpx=$(awk '$1 != "map" && $1 != "total" { split($2, d, "x"); printf "%.2f", d[1] * d[2] / 1e6 }' \
      "$work/floor_one.txt")
    printf '| %s x %s | %s | %.2f | %s | %.2f | %.2f | %s | %.2f | %.2f | %.0f | %s | %.2f | %s |\n' \
      "$n" "$n" \
      "$mpx" "$(awk -v f="$floor_ms" 'BEGIN { print f / 1000 }')" "$floor_mb" "$run_wall" \
      "$run_cpu" "$(ratio "$run_wall" "$(awk -v f="$floor_ms" 'BEGIN { print f / 1000 }')")" \
      "$(awk -v w="$run_wall" -v m="$mpx" 'BEGIN { print w / m }')" \
      "$(awk -v w="$run_cpu" -v m="$mpx" 'BEGIN { print w / m }')" "$run_mb" \
      "$(ratio "$run_mb" "$floor_mb")" \
      "$(awk -v f="$floor_hp_ms" 'BEGIN { print f / 1000 }')" \
      "$(ratio "$run_wall" "$(awk -v f="$floor_hp_ms" 'BEGIN { print f / 1000 }')")"
  done
  echo
}

# The clutter series: an N x N px room with 1 % random obstacle cells.
clutter_table() {
  local size map
  if ! "$bin/ag-make-example-maps" --help 2>/dev/null | grep -q -- --clutter; then
    notes+=("ag-make-example-maps has no --clutter: the clutter series did not run")
    return
  fi
  echo "#### Clutter: an N x N px room with 1 % random obstacle cells, ag-run --jobs 1"
  echo
  echo "| size | floor s | ag-run s | CPU s | × floor | merge s (compute) | peak MB |"
  echo "|---|--:|--:|--:|--:|--:|--:|"
  for size in $clutter_sizes; do
    "$bin/ag-make-example-maps" --clutter "$size" --out "$work" >/dev/null
    map="$work/clutter_$size.png"
    echo "bench-speed: clutter $size" >&2
    floor_of "$map"
    run_cold "$map"
    local merge_ms
    merge_ms=$("$bin/ag-inspect" --store "$work/series.db" --map "clutter_$size" |
      awk '$1 == "merge" && $NF == "*" { print $4 }')
    printf '| %s² | %.2f | %.2f | %.2f | %s | %.2f | %.0f |\n' "$size" \
      "$(awk -v f="$floor_ms" 'BEGIN { print f / 1000 }')" "$run_wall" "$run_cpu" \
      "$(ratio "$run_wall" "$(awk -v f="$floor_ms" 'BEGIN { print f / 1000 }')")" \
      "$(awk -v m="${merge_ms:-0}" 'BEGIN { print m / 1000 }')" "$run_mb"
  done
  echo
}

# own_cpu N COMMAND...: runs COMMAND N times with ag-bench-exec, each run its
# own process whose resource usage wait4 reports, and prints the median CPU
# milliseconds (user + system) of one such process, its median wall seconds
# and its median minor page faults: the command from its exec to its exit,
# start-up included, and nothing of the launcher. A failure becomes a note
# and prints nothing.
own_cpu() {
  local n=$1
  shift
  if ! "$bin/ag-bench-exec" --repeat "$n" -- "$@" >"$work/exec.txt" 2>&1; then
    notes+=("$(basename "$1") failed: $(tail -1 "$work/exec.txt")")
    return 1
  fi
  awk '{ printf "%s %.4f %s\n", $2, $8 / 1000, $10 }' "$work/exec.txt"
}

# loop_cpu N COMMAND...: the table's older method, kept as a column to set
# against own_cpu: N runs in one bash loop under /usr/bin/time, the mean CPU
# milliseconds per run. It also charges bash's fork of each run (the
# page-table copy and copy-on-write faults, several ms a process on a loaded
# machine) to the command. A failure becomes a note and prints nothing.
loop_cpu() {
  local n=$1 status=0
  shift
  /usr/bin/time -f '%e %U %S' -o "$work/time.txt" \
    bash -c 'n=$1; shift; for ((i = 0; i < n; ++i)); do "$@" >/dev/null 2>&1 || exit 1; done' \
    _ "$n" "$@" || status=$?
  if [ "$status" -ne 0 ]; then
    notes+=("$(basename "$1") failed: $*")
    return 1
  fi
  awk -v n="$n" '{ printf "%.1f\n", ($2 + $3) * 1000 / n }' "$work/time.txt"
}

# ag-render of every stage against that stage's compute, on lab_a and on
# lab_a tiled 2 x 2, in CPU time: the compute is ag-bench-stage's median CPU
# time of the stage's compute function on the stored inputs, run again in one
# process (the import: reading and decoding the file); the render is the
# median CPU time (user + system) of one whole ag-render process over --runs
# x 5 of them (own_cpu), start-up included. "start-up" is the same for
# `ag-render --help`; the column after the ratio is the render without it.
# The last column is the old method (loop_cpu), for comparison only. The wall
# columns are the store's elapsed compute time (for the import only the copy
# into the artifact) and ag-render's median.
render_table() {
  local source="$data/lab_a.png" map name stage ms repeat=$((5 * runs))
  [ -f "$source" ] || { notes+=("no $source: the render table did not run"); return; }
  echo "#### ag-render of each stage against the stage's compute time"
  echo
  local startup_ms startup_faults startup_loop
  read -r startup_ms _ startup_faults < <(own_cpu "$repeat" "$bin/ag-render" --help)
  startup_loop=$(loop_cpu "$repeat" "$bin/ag-render" --help)
  echo "ag-render's start-up (\`--help\`): ${startup_ms} ms of CPU, $startup_faults page faults"
  echo "(its own process, median of $repeat); ${startup_loop} ms in the old bash loop."
  echo
  echo -n "| map | stage | compute CPU ms | compute wall ms (store) | ag-render wall s"
  echo -n " | ag-render CPU ms | page faults | CPU render / compute | without start-up"
  echo " | bash-loop CPU ms (old method) |"
  echo "|---|---|--:|--:|--:|--:|--:|--:|--:|--:|"
  "$bin/ag-bench-tile" --tiles 2 "$source" "$work/lab_a_2x2.png" >/dev/null
  for map in "$source" "$work/lab_a_2x2.png"; do
    name=$(basename "${map%.*}")
    echo "bench-speed: render $name" >&2
    rm -f "$work"/series.db*
    "$bin/ag-run" --jobs 1 --store "$work/series.db" "$map" >/dev/null 2>&1 ||
      { notes+=("ag-run failed on $name: no render row"); continue; }
    for stage in import clean voronoi prune cut merge; do
      ms=$("$bin/ag-inspect" --store "$work/series.db" --map "$name" |
        awk -v s="$stage" '$1 == s && $NF == "*" { print $4 }')
      local compute_cpu cpu_ms wall faults loop_ms render=()
      compute_cpu=$("$bin/ag-bench-stage" --store "$work/series.db" --map "$name" \
        --stage "$stage" --repeat "$((2 * runs + 1))" | awk '{ print $4 }')
      render=("$bin/ag-render" --store "$work/series.db" --map "$name" --stage "$stage" \
        --out "$work/render.png")
      read -r cpu_ms wall faults < <(own_cpu "$repeat" "${render[@]}")
      loop_ms=$(loop_cpu "$repeat" "${render[@]}")
      printf '| %s | %s | %.1f | %.1f | %.3f | %.1f | %s | %s | %s | %s |\n' "$name" "$stage" \
        "${compute_cpu:-0}" "${ms:-0}" "${wall:-0}" "${cpu_ms:-0}" "${faults:-–}" \
        "$(ratio "$cpu_ms" "$compute_cpu")" \
        "$(ratio "$(awk -v c="$cpu_ms" -v s="$startup_ms" 'BEGIN { print c - s }')" \
          "$compute_cpu")" "${loop_ms:-–}"
    done
  done
  echo
}

# The 16 maps as the target measures them: ag-run --jobs 1 per map from a new
# store, start-up included, against each map's floor.
runs_table() {
  local map name
  local floor_sum=0 wall_sum=0 cpu_sum=0 peak=0
  echo "#### The 16 maps, ag-run --jobs 1 per map from a new store (start-up included)"
  echo
  echo "| map | floor s | ag-run s | CPU s | × floor | CPU × floor | peak MB |"
  echo "|---|--:|--:|--:|--:|--:|--:|"
  for map in "${maps[@]}"; do
    name=$(basename "${map%.*}")
    echo "bench-speed: ag-run $name" >&2
    floor_of "$map"
    run_cold "$map"
    local floor_s
    floor_s=$(awk -v f="$floor_ms" 'BEGIN { print f / 1000 }')
    printf '| %s | %.3f | %.2f | %.2f | %s | %s | %.0f |\n' "$name" "$floor_s" "$run_wall" \
      "$run_cpu" "$(ratio "$run_wall" "$floor_s")" "$(ratio "$run_cpu" "$floor_s")" "$run_mb"
    floor_sum=$(awk -v a="$floor_sum" -v b="$floor_s" 'BEGIN { print a + b }')
    wall_sum=$(awk -v a="$wall_sum" -v b="$run_wall" 'BEGIN { print a + b }')
    cpu_sum=$(awk -v a="$cpu_sum" -v b="$run_cpu" 'BEGIN { print a + b }')
    peak=$(awk -v a="$peak" -v b="$run_mb" 'BEGIN { print (b > a) ? b : a }')
  done
  printf '| **all %s maps** | %.2f | %.2f | %.2f | %s | %s | %.0f (max) |\n' "${#maps[@]}" \
    "$floor_sum" "$wall_sum" "$cpu_sum" "$(ratio "$wall_sum" "$floor_sum")" \
    "$(ratio "$cpu_sum" "$floor_sum")" "$peak"
  echo
}

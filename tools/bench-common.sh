# Sourced by the collection benchmarks (bench-collection.sh,
# bench-cluster-plan.sh): the options they share, the build, the work folder
# and the median. Expects `bench_name` and `bench_help_lines` ("2,18") set.

build_dir=build
build=1
work=""

# Handles one of the shared options (--build-dir DIR, --work DIR, --no-build,
# --help) at "$1"; sets bench_shift to the number of words it took.
bench_option() {
  case "$1" in
    --build-dir) build_dir="$2"; bench_shift=2 ;;
    --work) work="$2"; bench_shift=2 ;;
    --no-build) build=0; bench_shift=1 ;;
    -h|--help) sed -n "${bench_help_lines}p" "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
    *) echo "$bench_name: unknown argument '$1' (see --help)" >&2; exit 2 ;;
  esac
}

# Unless --no-build: installs what is missing and builds TARGET... (Release).
# Then sets `bin` (absolute) and `work` (a temporary folder removed at exit
# when --work was not given).
bench_prepare() {
  if [ "$build" = 1 ]; then
    tools/install-deps.sh >&2
    cmake -S . -B "$build_dir" -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null
    cmake --build "$build_dir" -j "$(nproc)" --target "$@" >&2
  fi
  bin="$(cd "$build_dir/bin" && pwd)"
  if [ -z "$work" ]; then
    work="$(mktemp -d)"
    trap 'rm -rf "$work"' EXIT
  fi
  mkdir -p "$work"
}

say() { echo "$bench_name: $*" >&2; }

# The median of the numbers on stdin, one a line.
median() { sort -g | awk '{v[NR]=$1} END {print (NR%2) ? v[(NR+1)/2] : (v[NR/2]+v[NR/2+1])/2}'; }

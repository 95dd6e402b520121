#!/usr/bin/env bash
# Counts what decides the segmentation besides the code's structure: the
# options that examples/options/default.pbtxt prints, and the named numeric
# constants in stages/. Prints one line per option and per constant (its
# file:line, name and value, and for a constant its class), then the totals.
#
#   tools/count-tunables.sh [--totals]
#
# --totals: the totals only.
#
# An option is a leaf field of default.pbtxt ("stage.message.field").
# merge.skip_passes, a list that is empty by default, is not printed there and
# not counted.
#
# A named numeric constant is, in stages/**/*.{h,cc}:
# - a name k<Upper>... that a `constexpr` declaration gives a value (each name
#   of a declaration that names several), or
# - a field with a default value in a `struct ...Params` (a pass's constants
#   gathered in one place, e.g. SplitCorridorParams).
# Each has one class:
# - tunable: a value someone chose that changes the areas (a width, a share,
#   a ratio, a count of openings). This is the count that issue-style targets
#   ("at most 30 named constants") refer to. Every constant is a tunable
#   unless it is listed under one of the classes below.
# - table: an array (neighbour offsets, lookup tables).
# - format: an artifact's format version (stages/common/stage_info.h).
# - bounds: a sanity bound on input or options (bad-input checks), not a
#   decision about a map.
# - implementation: how the work is done, not what it finds: parallel range
#   and chunk sizes, prefetch distances, hash table sizes, sentinels, bit
#   tricks, numeric tolerances and tie-breaks, direction names, fixed-point
#   scales, search radii and margins that only bound a search. Listed by name
#   below; a new constant of this kind must be added here to leave the
#   tunables.
set -euo pipefail
cd "$(dirname "$0")/.."
totals_only=0
case "${1:-}" in
  --totals) totals_only=1 ;;
  "") ;;
  -h | --help)
    sed -n '2,9p' "$0" | sed 's/^# \{0,1\}//'
    exit 0
    ;;
  *)
    echo "count-tunables: unknown argument '$1' (see --help)" >&2
    exit 2
    ;;
esac

IMPLEMENTATION='Ahead|Min[A-Za-z]*PerRange|Min[A-Za-z]*PerFilterRange|MinRange[A-Za-z]*'
IMPLEMENTATION+='|GapEdgesPerRange|Parallel[A-Za-z]*|Chunk[A-Za-z]*|SpatialSortOnPoolMin'
IMPLEMENTATION+='|Initial|MostSteps|Bits|Slots|Empty|Far|NoZero|Infinity|Unreached|Ray|NotHere'
IMPLEMENTATION+='|TwoPi|HalfGridLimit|MixedLimit|ShiftBits|Scale|Full|Row|One|Four|Near'
IMPLEMENTATION+='|BoxMargin|MaxNearer|SamePointPx|TieBreakStep|SlackPx|BucketPx|CornerCut'
IMPLEMENTATION+='|SampleStepPx|NarrowTolerancePx|East|South|West|North|SouthEast|SouthWest|NorthWest|NorthEast'
BOUNDS='MinResolutionM|MaxResolutionM|MaxOptionLengthM|MaxOptionAreaM2|MaxOriginM'

options=$(awk '
  /^[ \t]*#/ { next }
  /^[ \t]*[a-z_0-9]+ \{/ { stack[++depth] = $1; next }
  /^[ \t]*\}/ { depth--; next }
  /^[ \t]*[a-z_0-9]+: / {
    name = ""
    for (i = 1; i <= depth; i++) name = name stack[i] "."
    field = $1; sub(":", "", field)
    value = $0; sub(/^[ \t]*[a-z_0-9]+: /, "", value)
    printf "option\t%s:%d\t%s%s = %s\n", FILENAME, FNR, name, field, value
  }' examples/options/default.pbtxt)

constants=$(find stages -name '*.h' -o -name '*.cc' | LC_ALL=C sort | xargs perl -ne '
  BEGIN { ($impl, $bounds) = @ARGV[0, 1]; splice(@ARGV, 0, 2); }
  sub class_of {
    my ($name, $array) = @_;
    return "table" if $array;
    return "format" if $name =~ /FormatVersion$/;
    return "bounds" if $name =~ /^k(?:$bounds)$/;
    return "implementation" if $name =~ /^k(?:$impl)$/;
    return "tunable";
  }
  if (/^\s*struct (\w+Params) \{/) { $params = $1; }
  elsif ($params && /^\};/) { $params = ""; }
  elsif ($params && /^\s*(?:double|float|int|bool|size_t|int64_t)\s+(\w+)\s*=\s*([^;]+);/) {
    print "constant\t$ARGV:$.\t${params}::$1 = $2\ttunable\n";
  }
  if (/\bconstexpr\b/ && !/\(/ || /\bconstexpr\b[^(]*\bk[A-Z]\w*\s*(?:\[[^\]]*\])?\s*=/) {
    my $decl = $_;
    $decl =~ s{//.*}{};
    while ($decl =~ /\b(k[A-Z]\w*)\s*(\[[^\]]*\])?\s*=\s*(\{[^}]*\}|[^,;]+)/g) {
      my ($name, $array, $value) = ($1, $2, $3);
      next if $value =~ /"/;
      $value =~ s/\s+$//;
      printf "constant\t%s:%d\t%s = %s\t%s\n", $ARGV, $., $name, $value, class_of($name, $array);
    }
  }
  close ARGV if eof;
' "$IMPLEMENTATION" "$BOUNDS")

if [ "$totals_only" = 0 ]; then
  printf '%s\n' "$options"
  printf '%s\n' "$constants"
fi
count() { grep -c "$1" <<<"$2" || true; }
echo "options in examples/options/default.pbtxt: $(count '^option' "$options")"
echo "named numeric constants in stages/: $(count '^constant' "$constants")"
for class in tunable implementation table format bounds; do
  echo "  $class: $(count "	$class\$" "$constants")"
done
echo "tunable constants outside stages/cut and stages/match:" \
  "$(grep -P '\ttunable$' <<<"$constants" | grep -vcP '\tstages/(cut|match)/' || true)"

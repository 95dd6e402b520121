#!/usr/bin/env bash
# Lists the tests that ctest's last run in BUILD_DIR skipped, one line each
# with the reason the test gave (GTEST_SKIP), on stderr. With --fail-label
# REGEX it exits 1 when one of them carries a ctest label matching REGEX
# (.ci/run: no test labelled pipeline may skip, so that a trick that stops
# working, or a test that stops running, cannot hide).
#   tools/skipped-tests.sh BUILD_DIR [--fail-label REGEX]
set -euo pipefail
if [ $# -lt 1 ] || [ "$1" = --help ] || [ "$1" = -h ]; then
  sed -n '2,7p' "$0" | sed 's/^# \{0,1\}//'
  [ $# -ge 1 ] && exit 0
  exit 2
fi
build=$1
shift
fail_label=""
while [ $# -gt 0 ]; do
  case "$1" in
    --fail-label) fail_label=$2; shift 2 ;;
    *) echo "skipped-tests: unknown argument '$1' (see --help)" >&2; exit 2 ;;
  esac
done
log="$build/Testing/Temporary/LastTest.log"
[ -f "$log" ] || { echo "skipped-tests: no $log (run ctest first)" >&2; exit 2; }

# "NAME<TAB>REASON" for every test whose output ctest matched as skipped; the
# reason is what GTEST_SKIP printed between "file:line: Skipped" and
# "[  SKIPPED ]".
skipped=$(awk '
  /^[0-9]+\/[0-9]+ Test: / { name = $3; reason = ""; in_reason = 0; next }
  /: Skipped$/ { in_reason = 1; next }
  /^\[  SKIPPED \]/ { in_reason = 0; next }
  in_reason && NF { reason = reason (reason == "" ? "" : " ") $0; next }
  /^Skip regular expression found in output/ { print name "\t" (reason == "" ? "(no reason given)" : reason) }
' "$log")
[ -n "$skipped" ] || exit 0
while IFS=$'\t' read -r name reason; do
  echo "skipped: $name: $reason" >&2
done <<<"$skipped"

[ -n "$fail_label" ] || exit 0
labelled=$(ctest --test-dir "$build" -N -L "$fail_label" | sed -n 's/^ *Test *#[0-9]*: //p')
bad=$(cut -f1 <<<"$skipped" | grep -Fxf <(printf '%s\n' "$labelled") || true)
if [ -n "$bad" ]; then
  echo "skipped-tests: $(wc -l <<<"$bad") test(s) labelled '$fail_label' skipped in $build:" \
    "$(tr '\n' ' ' <<<"$bad")" >&2
  exit 1
fi

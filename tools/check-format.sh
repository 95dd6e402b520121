#!/usr/bin/env bash
# Fails when a C++ file differs from what clang-format (.clang-format) writes.
# Usage: tools/check-format.sh [REF]   checks the files changed since REF
#        (committed or not); without REF, every tracked .cc/.h file.
set -euo pipefail
cd "$(dirname "$0")/.."
if [ $# -ge 1 ]; then
  mapfile -t files < <(git diff --name-only --diff-filter=d "$1" -- '*.cc' '*.h')
else
  mapfile -t files < <(git ls-files '*.cc' '*.h')
fi
bad=()
for file in "${files[@]}"; do
  [ -f "$file" ] || continue
  if ! clang-format --style=file "$file" | cmp -s - "$file"; then bad+=("$file"); fi
done
if [ ${#bad[@]} -gt 0 ]; then
  echo "check-format: ${#bad[@]} file(s) differ from clang-format (run clang-format -i on them):" >&2
  printf '  %s\n' "${bad[@]}" >&2
  exit 1
fi
echo "check-format: ${#files[@]} file(s) formatted"

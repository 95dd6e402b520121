#!/usr/bin/env bash
# Installs what is missing and builds into build/.
#   tools/build.sh             everything (the test suite's packages too)
#   tools/build.sh TARGET...   only those targets and what they link (the
#                              build's packages only), e.g. ag-run ag-render
# CMake configures build/ once; after that the build itself re-runs it when a
# CMake file changed, so a build of an unchanged tree relinks nothing.
set -euo pipefail
cd "$(dirname "$0")/.."
if [ $# -gt 0 ]; then tools/install-deps.sh build; else tools/install-deps.sh; fi
if [ ! -f build/build.ninja ]; then
  echo "build: first build into build/ (about 7 minutes on 2 cores; later builds are incremental)"
  cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null
fi
targets=()
for target in "$@"; do targets+=(--target "$target"); done
cmake --build build -j "$(nproc)" "${targets[@]}"

#!/usr/bin/env bash
# Installs dependencies (if missing) and builds everything into build/.
set -euo pipefail
cd "$(dirname "$0")/.."
tools/install-deps.sh
if [ ! -f build/build.ninja ]; then
  echo "build: first build into build/ (about 7 minutes on 2 cores; later builds are incremental)"
fi
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build -j "$(nproc)"

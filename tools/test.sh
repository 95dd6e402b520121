#!/usr/bin/env bash
# Installs dependencies, builds, and runs the whole test suite through ctest.
set -euo pipefail
cd "$(dirname "$0")/.."
tools/build.sh
echo "test: running the suite (ctest; a few minutes on 2 cores)"
ctest --test-dir build --output-on-failure -j "$(nproc)" "$@"

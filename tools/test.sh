#!/usr/bin/env bash
# Installs dependencies, builds, and runs the whole test suite through ctest;
# then names every skipped test with its reason (tools/skipped-tests.sh).
set -euo pipefail
cd "$(dirname "$0")/.."
tools/build.sh
echo "test: running the suite (ctest; a few minutes on 2 cores)"
status=0
ctest --test-dir build --output-on-failure -j "$(nproc)" "$@" || status=$?
tools/skipped-tests.sh build
exit "$status"

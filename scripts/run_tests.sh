#!/usr/bin/env bash
# The project's test command: set up (packages, corpus, Release build), then
# run the whole CTest suite.
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$ROOT"

scripts/setup.sh
echo "[run_tests] ctest --test-dir build --output-on-failure -j2 --timeout 900"
exec ctest --test-dir build --output-on-failure -j2 --timeout 900

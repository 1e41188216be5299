#!/usr/bin/env bash
# The fuzz smoke runs (.ci/run, after the sanitizer job): each libFuzzer harness of the clang
# AddressSanitizer + UndefinedBehaviorSanitizer build (build-asan/, scripts/build_sanitized.sh)
# fuzzes its generated seeds for 30 s. Kept out of the README's test command: that build
# alone takes longer than the rest of the suite.
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$ROOT"
BUILD="${ACD_SANITIZER_BUILD:-build-asan}"
scripts/build_sanitized.sh fuzzers
echo "[run_fuzz_smoke] ctest --test-dir $BUILD -L fuzz -j2"
exec ctest --test-dir "$BUILD" -L fuzz --output-on-failure -j2 --timeout 900

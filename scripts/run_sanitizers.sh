#!/usr/bin/env bash
# The sanitizer job (.ci/run, after the main test command): libacd's tests and the acd command's
# tests, built with clang's AddressSanitizer (leaks included) and UndefinedBehaviorSanitizer in
# build-asan/, run under ctest. Fails on a failing test and on any sanitizer report, including
# one from a child `acd` process whose exit code a test expected to be non-zero: every report
# is written to build-asan/sanitizer-logs/ and the job fails if that folder is not empty.
# Tests named in scripts/sanitizer_skip.txt are left out (too slow under the sanitizers; they
# run in the main suite). The fuzz smoke runs are left out too: the main suite runs them.
set -uo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$ROOT"
BUILD="${ACD_SANITIZER_BUILD:-build-asan}"
start=$(date +%s)

scripts/build_sanitized.sh || exit 1  # everything: every test program of the suite

LOGS="$ROOT/$BUILD/sanitizer-logs"
rm -rf "$LOGS"
mkdir -p "$LOGS"
export ASAN_OPTIONS="detect_leaks=1:halt_on_error=1:strict_string_checks=1:check_initialization_order=1:log_path=$LOGS/asan"
export UBSAN_OPTIONS="halt_on_error=1:print_stacktrace=1:log_path=$LOGS/ubsan"
export LSAN_OPTIONS="suppressions=$ROOT/scripts/lsan_suppressions.txt:print_suppressions=0"

skip="$(sed -e 's/#.*//' -e 's/[[:space:]]*$//' -e '/^$/d' scripts/sanitizer_skip.txt | paste -sd'|' -)"
exclude=()
if [[ -n "$skip" ]]; then
    exclude=(-E "$skip")
    echo "[run_sanitizers] skipped (scripts/sanitizer_skip.txt): $skip"
fi
echo "[run_sanitizers] ctest --test-dir $BUILD -LE fuzz ${exclude[*]} -j2 --timeout 1800"
ctest --test-dir "$BUILD" -LE fuzz "${exclude[@]}" --output-on-failure -j2 --timeout 1800
tests=$?

reports=("$LOGS"/*)
if [[ -e "${reports[0]}" ]]; then
    echo "[run_sanitizers] FAILED: ${#reports[@]} sanitizer report(s):" >&2
    for r in "${reports[@]}"; do
        echo "----- $r" >&2
        head -n 60 "$r" >&2
    done
    exit 1
fi
echo "[run_sanitizers] no sanitizer reports; ctest exit $tests; $(( $(date +%s) - start )) s in all"
exit "$tests"

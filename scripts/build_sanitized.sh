#!/usr/bin/env bash
# Configures and builds the clang AddressSanitizer + UndefinedBehaviorSanitizer build in
# build-asan/: libacd, the acd command, the test program and the fuzz harnesses, all instrumented
# (docs/FUZZING.md). Builds the given targets, or everything when none is given.
#   scripts/build_sanitized.sh fuzzers
#   scripts/build_sanitized.sh acd_tests acd_cli pointloc
# ACD_SANITIZERS picks the sanitizers (default address,undefined); with ACD_SANITIZERS=undefined
# and ACD_SANITIZER_BUILD=build-ubsan the harnesses run several times faster, for long campaigns
# whose corpus is then replayed under ASan (docs/FUZZING.md).
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$ROOT"
BUILD="${ACD_SANITIZER_BUILD:-build-asan}"
SANITIZERS="${ACD_SANITIZERS:-address,undefined}"
JOBS="${ACD_JOBS:-$(nproc)}"

if ! command -v clang++ >/dev/null 2>&1; then
    echo "build_sanitized: clang++ not found (scripts/setup.sh installs clang)" >&2
    exit 1
fi
# -O2 and NDEBUG, without the build type's -g: cmake/sanitizers.cmake adds the line tables the
# reports need. The applications other than acd and pointloc, and the Python module (an ASan
# extension cannot be loaded into an uninstrumented interpreter), are left out: their tests run
# in the main build.
mkdir -p "$BUILD"
if ! cmake -S . -B "$BUILD" -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=RelWithDebInfo \
        -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O2 -DNDEBUG" -DCMAKE_C_FLAGS_RELWITHDEBINFO="-O2 -DNDEBUG" \
        -DACD_SANITIZE="$SANITIZERS" -DACD_BUILD_FUZZERS=ON -DACD_APPLICATIONS= -DACD_BUILD_PYTHON=OFF >"$BUILD/configure.log" 2>&1; then
    cat "$BUILD/configure.log" >&2
    echo "build_sanitized: cmake configure failed" >&2
    exit 1
fi
targets=()
for t in "$@"; do targets+=(--target "$t"); done
echo "[build_sanitized] building ${*:-everything} in $BUILD with $JOBS jobs"
nice cmake --build "$BUILD" -j"$JOBS" "${targets[@]}"

#!/usr/bin/env bash
# Runs one fuzz harness on its seeds with the project's settings (per-input time limit,
# input size, dictionary); extra arguments go to libFuzzer.
#   fuzz/run.sh BUILD/fuzz/fuzz_read_ply SEEDS_DIR -max_total_time=60
# SEEDS_DIR is what fuzz/make_seeds.py wrote. New inputs go to $FUZZ_CORPUS/<harness> when set
# (kept between runs, as in a campaign), else to a scratch folder removed at the end; crashes,
# timeouts and leaks are written to $FUZZ_ARTIFACTS (default: the current folder).
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
binary="$1" seeds="$2"
shift 2
name="$(basename "$binary")"

case "$name" in
    fuzz_read_obj_objects) kind=obj ;;
    fuzz_read_scene) kind=scene ;;  # selector byte + a glTF, GLB, COLLADA, 3MF or FBX file
    fuzz_read_*) kind="${name#fuzz_read_}" ;;
    fuzz_decompose) kind=decompose ;;
    *) echo "run.sh: unknown harness $name" >&2; exit 2 ;;
esac
if [[ "$kind" == decompose ]]; then
    # A few dozen faces, at most 24 components, the wrap only at tau >= 0.1: the slowest input seen took 0.8 s in the
    # Release build and about 30 s under the sanitizers on a loaded machine; 120 s means a hang.
    settings=(-timeout=120 -max_len=256)
elif [[ "$kind" == scene ]]; then
    # Read in a child with an 8 s cap, as the acd command reads scenes (assimp aborts on some
    # inputs and allocates without bound on others): 30 s means a hang of the parent.
    settings=(-timeout=30 -max_len=16384 "-dict=$here/dict/$kind.dict")
else
    settings=(-timeout=10 -max_len=16384 "-dict=$here/dict/$kind.dict")
fi

if [[ -n "${FUZZ_CORPUS:-}" ]]; then
    corpus="$FUZZ_CORPUS/$name"
    mkdir -p "$corpus"
else
    corpus="$(mktemp -d)"
    trap 'rm -rf "$corpus"' EXIT
fi
artifacts="${FUZZ_ARTIFACTS:-$PWD}"
mkdir -p "$artifacts"

# Leaks count as findings; a report stops the run (libFuzzer exits non-zero).
export ASAN_OPTIONS="${ASAN_OPTIONS:-detect_leaks=1}"
export UBSAN_OPTIONS="${UBSAN_OPTIONS:-halt_on_error=1:print_stacktrace=1}"
"$binary" "${settings[@]}" -rss_limit_mb=2048 -print_final_stats=1 \
    "-artifact_prefix=$artifacts/$name-" "$@" "$corpus" "$seeds/$kind"

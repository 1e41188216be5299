#!/usr/bin/env bash
# Instruction counts of `acd decompose` under callgrind: a figure that does not drift with the
# load of a shared machine, for comparing two versions. Prints a Markdown table.
#
#   bench/callgrind.sh [--models "armadillo eight"] [--tau 0.05] [--revs "83ffb86 HEAD"]
#                      [--out DIR]
#
#   --models  corpus models, data/meshes/NAME.off (default: armadillo)
#   --tau     the concavity tolerance (default 0.05)
#   --revs    git revisions to compare (default: HEAD); each is checked out in OUT/src-REV
#             (a git worktree) and built there (acd command only, see below)
#   --out     where builds and runs go (default out/callgrind)
#
# valgrind computes every floating-point operation rounded to nearest, whatever mode the program
# sets, and CGAL's interval arithmetic switches to rounding upward: under valgrind its filters
# give wrong answers (a 2D triangulation loops, a free() aborts). So the measured builds define
# CGAL_ALWAYS_ROUND_TO_NEAREST, with which CGAL widens each interval by one ulp instead of
# switching modes; the output is the same as the normal build's (it only tests the filters
# differently). Each run: `valgrind --tool=callgrind acd decompose MODEL -t TAU --threads 1`;
# the figure is callgrind's total "I refs". Needs valgrind (apt-get install valgrind).
set -euo pipefail

ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$ROOT"

MODELS="armadillo"
TAU="0.05"
REVS="HEAD"
OUT="out/callgrind"

usage() { sed -n '2,19p' "$0" | sed 's/^# \{0,1\}//'; }
while [[ $# -gt 0 ]]; do
    case "$1" in
        --models) MODELS="$2"; shift 2 ;;
        --tau) TAU="$2"; shift 2 ;;
        --revs) REVS="$2"; shift 2 ;;
        --out) OUT="$2"; shift 2 ;;
        -h|--help) usage; exit 0 ;;
        *) echo "callgrind: unknown option $1" >&2; usage >&2; exit 2 ;;
    esac
done
command -v valgrind >/dev/null 2>&1 || { echo "callgrind: valgrind missing (apt-get install valgrind)" >&2; exit 1; }
for m in $MODELS; do
    [[ -f "data/meshes/$m.off" ]] || { echo "callgrind: data/meshes/$m.off not found (scripts/fetch_corpus.sh)" >&2; exit 1; }
done
mkdir -p "$OUT"
OUT="$(cd "$OUT" && pwd)"

# The acd command of one revision, built with CGAL rounding to nearest.
build_rev() {
    local rev="$1" sha src build
    sha="$(git rev-parse --short "$rev")"
    src="$OUT/src-$sha"
    build="$OUT/build-$sha"
    if [[ ! -d "$src" ]]; then
        git worktree add --detach "$src" "$sha" >&2
    fi
    if [[ ! -x "$build/bin/acd" ]]; then
        echo "[callgrind] building $sha" >&2
        local launcher=()
        command -v ccache >/dev/null 2>&1 && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
        cmake -S "$src" -B "$build" -DCMAKE_BUILD_TYPE=Release "${launcher[@]}" \
            -DCMAKE_CXX_FLAGS="-DCGAL_ALWAYS_ROUND_TO_NEAREST" \
            -DACD_BUILD_TESTS=OFF -DACD_BUILD_PYTHON=OFF -DACD_FUZZ_SMOKE=OFF >"$build.cmake.log" 2>&1 ||
            { echo "callgrind: configuring $sha failed ($build.cmake.log)" >&2; exit 1; }
        cmake --build "$build" --target acd_cli -j "$(nproc)" >"$build.build.log" 2>&1 ||
            { echo "callgrind: building $sha failed ($build.build.log)" >&2; exit 1; }
    fi
    echo "$sha"
}

declare -A COUNT PARTS
SHAS=()
for rev in $REVS; do
    sha="$(build_rev "$rev")"
    SHAS+=("$sha")
    for m in $MODELS; do
        run="$OUT/run-$sha-$m-t$TAU"
        if [[ ! -f "$run/callgrind.log" ]] || ! grep -q "I *refs" "$run/callgrind.log"; then
            echo "[callgrind] $sha $m tau=$TAU" >&2
            rm -rf "$run"; mkdir -p "$run"
            valgrind --tool=callgrind --callgrind-out-file="$run/callgrind.out" \
                "$OUT/build-$sha/bin/acd" decompose "data/meshes/$m.off" -t "$TAU" -o "$run/out" -q --threads 1 \
                2>"$run/callgrind.log" || true
        fi
        COUNT[$sha,$m]="$(sed -n 's/.*I *refs: *\([0-9,]*\).*/\1/p' "$run/callgrind.log" | tr -d ,)"
        PARTS[$sha,$m]="$(ls "$run/out" 2>/dev/null | grep -c '^component_' || true)"
    done
done

echo "Instruction counts (callgrind, \`acd decompose MODEL -t $TAU --threads 1\`, 10⁹ instructions):"
echo
header="| model |"; rule="|---|"
for sha in "${SHAS[@]}"; do header+=" $sha | parts |"; rule+="---:|---:|"; done
(( ${#SHAS[@]} > 1 )) && { header+=" last / first |"; rule+="---:|"; }
echo "$header"; echo "$rule"
for m in $MODELS; do
    row="| $m |"
    for sha in "${SHAS[@]}"; do
        c="${COUNT[$sha,$m]}"
        if [[ -n "$c" ]]; then row+=" $(awk -v c="$c" 'BEGIN{printf "%.2f", c/1e9}') | ${PARTS[$sha,$m]} |"
        else row+=" failed | – |"; fi
    done
    if (( ${#SHAS[@]} > 1 )); then
        first="${COUNT[${SHAS[0]},$m]}"; last="${COUNT[${SHAS[-1]},$m]}"
        if [[ -n "$first" && -n "$last" ]]; then row+=" $(awk -v a="$first" -v b="$last" 'BEGIN{printf "%.2f", b/a}') |"
        else row+=" – |"; fi
    fi
    echo "$row"
done

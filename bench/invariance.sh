#!/usr/bin/env bash
# Is acd's decomposition the same when the model is moved rigidly? For each closed corpus model
# and tau, decomposes the original and 10 moved copies (8 seeded random rotations with
# translations, a 1e-9 x diagonal translation, the exact 90-degree turn (x,y,z) -> (-y,x,z))
# and compares them: same part count, and components matched by their centroids mapped back
# through the motion, with volumes equal within 1e-6 relative (bench/invariance.py says how).
#
#   bench/invariance.sh [--models "elephant knot"] [--taus "0.05 0.1"] [--threads N]
#                       [--jobs N] [--out DIR] [--fresh] [--acd PATH] [--invariant]
#
#   --models   default: the 10 closed corpus models     --taus     default: 0.05 0.1
#   --threads  acd's --threads (default 2)               --jobs     runs at a time (default 1)
#   --out      cache (default out/invariance): finished runs are reused unless --fresh
#   --data     folder of MODEL.off files (default data/meshes: the corpus)
#   --invariant  pass acd's --invariant (the default of the acd command since 2026-11-25; for older builds)
#   --flags "F"  more flags for every decompose (for example "--no-union")
#
# Prints a Markdown table model x tau: motions matching out of 10, the largest relative volume
# difference between matched components, the part counts seen. Exits 1 when some model has
# fewer than 9 of 10 motions matching (or a run failed). Exit 4 of decompose (some component
# unresolved) is a result, counted in the table.
set -euo pipefail

ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$ROOT"

MODELS="armadillo bunny00 camel cow dino eight elephant handle homer knot"
TAUS="0.05 0.1"
THREADS=2
JOBS=1
OUT="out/invariance"
DATA="data/meshes"
FRESH=0
ACD="build/bin/acd"
PY=/usr/bin/python3
EXTRA=()

usage() { sed -n '2,21p' "$0" | sed 's/^# \{0,1\}//'; }
while [[ $# -gt 0 ]]; do
    case "$1" in
        --data) DATA="$2"; shift 2 ;;
        --models) MODELS="$2"; shift 2 ;;
        --taus) TAUS="$2"; shift 2 ;;
        --threads) THREADS="$2"; shift 2 ;;
        --jobs) JOBS="$2"; shift 2 ;;
        --out) OUT="$2"; shift 2 ;;
        --fresh) FRESH=1; shift ;;
        --acd) ACD="$2"; shift 2 ;;
        --invariant) EXTRA+=(--invariant); shift ;;
        --flags) read -r -a more <<<"$2"; EXTRA+=("${more[@]}"); shift 2 ;;
        -h|--help) usage; exit 0 ;;
        *) echo "invariance: unknown option $1" >&2; usage >&2; exit 2 ;;
    esac
done
[[ "$JOBS" =~ ^[1-9][0-9]*$ ]] || { echo "invariance: --jobs needs a positive integer" >&2; exit 2; }
[[ -x "$ACD" ]] || { echo "invariance: $ACD not found; build the acd_cli target first" >&2; exit 1; }
(( FRESH )) && rm -rf "$OUT"
mkdir -p "$OUT/meshes"

# One decomposition into DIR, skipped when DIR/rc exists (written last).
run_one() {
    local mesh="$1" tau="$2" dir="$3" rc=0
    [[ -f "$dir/rc" ]] && return 0
    rm -rf "$dir"; mkdir -p "$dir"
    echo "[invariance] $dir" >&2
    "$ACD" decompose "$mesh" -t "$tau" -o "$dir" -q --threads "$THREADS" "${EXTRA[@]}" 2>"$dir/stderr.txt" || rc=$?
    if (( rc != 0 && rc != 4 && rc != 8 )); then
        echo "[invariance]   FAILED (exit $rc, see $dir/stderr.txt)" >&2; return 1
    fi
    echo "$rc" >"$dir/rc"
}

failed=0
for model in $MODELS; do
    src="$DATA/$model.off"
    [[ -f "$src" ]] || { echo "invariance: $src not found (scripts/fetch_corpus.sh)" >&2; exit 1; }
    for motion in $($PY bench/invariance.py motions); do
        moved="$OUT/meshes/$model-${motion/:/}.off"
        [[ -f "$moved" && -f "${moved%.off}.json" ]] || $PY bench/invariance.py move "$src" "$moved" "$motion"
    done
    for tau in $TAUS; do
        for motion in orig $($PY bench/invariance.py motions); do
            mesh="$src"
            [[ $motion != orig ]] && mesh="$OUT/meshes/$model-${motion/:/}.off"
            while (( $(jobs -rp | wc -l) >= JOBS )); do wait -n || failed=1; done
            run_one "$mesh" "$tau" "$OUT/$model/t$tau/${motion/:/}" &
        done
    done
done
while (( $(jobs -rp | wc -l) > 0 )); do wait -n || failed=1; done

$PY bench/invariance.py table "$OUT" $TAUS -- $MODELS || failed=1
exit "$failed"

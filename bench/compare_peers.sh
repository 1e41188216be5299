#!/usr/bin/env bash
# acd against CoACD and V-HACD at equal fidelity: how many parts acd needs to reach each peer's
# excess and IoU on the closed corpus models. Prints a Markdown table.
#
#   bench/compare_peers.sh [--models "armadillo dino"] [--taus "0.2 0.1 ..."] [--threads N]
#                          [--jobs N] [--out DIR] [--fresh] [--acd PATH]
#
#   --models   closed corpus models (default: the 10 of bench/peers-corpus.tsv with an inside;
#              the open mushroom and ChineseDragon-10kv have no IoU or excess and are skipped)
#   --taus     starting taus (default below); more are added, by factors of 0.7, while a peer
#              figure lies outside acd's runs (between tau 0.004 and 1)
#   --threads  acd's --threads (default 2)      --jobs  runs at a time (default 1)
#   --out      cache of runs (default out/compare_peers); existing runs are reused
#   --fresh    forget the cache and re-do every run
#   ACD_COMMIT=LABEL (environment): what the runs are labelled with when --acd is a binary built
#              elsewhere (default: the checkout's commit)
#
# Each run: `acd decompose data/meshes/MODEL.off -t TAU -o OUT/MODEL/tTAU -q` (exit 4, some
# component unresolved, is a result: kept and flagged †), then
# `acd evaluate MODEL HULLS.obj --json --samples 1000000` (the peers' figures used 1e6 samples).
# excess = max(hull_outside_max, model_to_hulls_max), as bench/peers-corpus.tsv defines it.
# Interpolation: per model and figure, the runs are reduced to their envelope (by parts, keep
# a run only when its figure beats every run with fewer parts); the target is bracketed by the
# fewest-parts envelope run that meets it and the envelope run before it, and acd's parts are
# interpolated linearly in log(parts) against the figure between those two. So when excess or
# IoU is not monotone in tau, a tau whose figure is worse than a coarser run's is ignored.
# Raw figures of every run: OUT/runs.tsv. The table: docs/BENCHMARKS.md explains it.
set -euo pipefail

ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$ROOT"

MODELS="armadillo bunny00 camel cow dino eight elephant handle homer knot"
TAUS="0.2 0.14 0.1 0.085 0.07 0.06 0.05 0.042 0.035 0.03 0.025 0.02 0.0175 0.015 0.0125"
THREADS=2
JOBS=1
OUT="out/compare_peers"
FRESH=0
ACD="build/bin/acd"
PEERS="bench/peers-corpus.tsv"
MAX_ROUNDS=8

usage() { sed -n '2,27p' "$0" | sed 's/^# \{0,1\}//'; }
while [[ $# -gt 0 ]]; do
    case "$1" in
        --models) MODELS="$2"; shift 2 ;;
        --taus) TAUS="$2"; shift 2 ;;
        --threads) THREADS="$2"; shift 2 ;;
        --jobs) JOBS="$2"; shift 2 ;;
        --out) OUT="$2"; shift 2 ;;
        --fresh) FRESH=1; shift ;;
        --acd) ACD="$2"; shift 2 ;;
        -h|--help) usage; exit 0 ;;
        *) echo "compare_peers: unknown option $1" >&2; usage >&2; exit 2 ;;
    esac
done
[[ "$JOBS" =~ ^[1-9][0-9]*$ ]] || { echo "compare_peers: --jobs needs a positive integer" >&2; exit 2; }
[[ -x "$ACD" ]] || { echo "compare_peers: $ACD not found; build the acd_cli target first" >&2; exit 1; }
for m in $MODELS; do
    [[ -f "data/meshes/$m.off" ]] || { echo "compare_peers: data/meshes/$m.off not found (scripts/fetch_corpus.sh)" >&2; exit 1; }
done
(( FRESH )) && rm -rf "$OUT"
mkdir -p "$OUT"

# What is measured: the commit ("+dirty" when the library or the command differ from it), or
# $ACD_COMMIT when --acd is a binary built elsewhere.
if [[ -n "${ACD_COMMIT:-}" ]]; then
    COMMIT="$ACD_COMMIT"
else
    COMMIT="$(git rev-parse --short HEAD 2>/dev/null || echo unknown)"
    git diff --quiet HEAD -- libacd apps 2>/dev/null || COMMIT="$COMMIT+dirty"
fi

# One run, skipped when its cached result is complete (rc written last).
run_one() {
    local model="$1" tau="$2" dir="$OUT/$1/t$2" rc=0
    [[ -f "$dir/rc" ]] && return 0
    rm -rf "$dir"; mkdir -p "$dir"
    echo "[compare_peers] $model tau=$tau" >&2
    "$ACD" decompose "data/meshes/$model.off" -t "$tau" -o "$dir" -q --threads "$THREADS" 2>"$dir/stderr.txt" || rc=$?
    if (( rc != 0 && rc != 4 )); then
        echo "[compare_peers]   FAILED (exit $rc, see $dir/stderr.txt)" >&2
        echo "$rc" >"$dir/rc"; return 1   # not retried before --fresh
    fi
    "$ACD" evaluate "data/meshes/$model.off" "$dir/hulls.obj" --json --samples 1000000 \
        --threads "$THREADS" >"$dir/eval.json" 2>>"$dir/stderr.txt" ||
        { echo "[compare_peers]   evaluate FAILED (see $dir/stderr.txt)" >&2; return 1; }
    rm -f "$dir"/component_*.off   # the hulls and the figures are what is kept
    echo "$COMMIT" >"$dir/commit"
    echo "$rc" >"$dir/rc"
}

# Runs "MODEL TAU" lines from stdin, JOBS at a time.
failed=0
run_all() {
    local model tau
    while read -r model tau; do
        while (( $(jobs -rp | wc -l) >= JOBS )); do wait -n || failed=1; done
        run_one "$model" "$tau" &
    done
    while (( $(jobs -rp | wc -l) > 0 )); do wait -n || failed=1; done
}

for m in $MODELS; do for t in $TAUS; do echo "$m $t"; done; done | { run_all; exit $failed; } || failed=1
prev=""
for ((round = 1; round <= MAX_ROUNDS; round++)); do
    more="$(/usr/bin/python3 bench/compare_peers.py extend "$OUT" "$PEERS" $MODELS)"
    [[ -z "$more" || "$more" == "$prev" ]] && break   # (the same request again: those runs failed)
    prev="$more"
    echo "[compare_peers] extending the tau range: $(echo "$more" | tr '\n' ' ')" >&2
    echo "$more" | { run_all; exit $failed; } || failed=1
done

/usr/bin/python3 bench/compare_peers.py table "$OUT" "$PEERS" $MODELS
exit "$failed"

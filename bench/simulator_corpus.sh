#!/usr/bin/env bash
# Simulator-ready hulls over the mesh corpus: every model decomposed with a vertex cap and a
# hull budget (PhysX GPU limits by default), each result measured with `acd evaluate`, and a
# Markdown table printed beside V-HACD's figures at its defaults (64 hulls).
#
#   bench/simulator_corpus.sh [--tau T] [--max-hull-vertices K] [--max-hulls N]
#                             [--models "elephant camel"] [--samples S] [--peers FILE]
#                             [--out DIR] [--acd PATH]
#
#   --tau                 concavity tolerance (default 0.05)
#   --max-hull-vertices   K (default 60)
#   --max-hulls           N (default 64)
#   --models              corpus names, files data/meshes/NAME.off (default: all 12)
#   --samples             Monte-Carlo points for acd evaluate (default 1000000, as the peers' table)
#   --peers DIR           bench/compare_peers.sh's output (default out/compare_peers); V-HACD's
#                         run at its defaults (64 hulls) is joined in where it is there
#   --out DIR             where runs write (default out/simulator)
#   --acd PATH            the CLI (default build/bin/acd)
#   --table-only          no runs: the table from the outputs already in --out
#
# Per model: `acd decompose MODEL -t T -o DIR/exact -q` (uncapped hulls, for the IoU they would
# give) and `acd decompose MODEL -t T --max-hull-vertices K --max-hulls N -o DIR/capped -q`;
# then `acd evaluate MODEL DIR/{exact,capped}/hulls.obj --json --samples S`. Open meshes
# (mushroom, ChineseDragon-10kv) have no inside: only counts. Table to stdout, progress to
# stderr; exit 1 if a run failed or a budget was not met.
set -euo pipefail

ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$ROOT"

TAU=0.05
K=60
N=64
MODELS="elephant armadillo bunny00 camel cow dino homer handle knot eight mushroom ChineseDragon-10kv"
SAMPLES=1000000
PEERS="out/compare_peers"
OUTROOT="out/simulator"
ACD="build/bin/acd"
TABLE_ONLY=0

usage() { sed -n '2,26p' "$0" | sed 's/^# \{0,1\}//'; }
while [[ $# -gt 0 ]]; do
    case "$1" in
        --tau) TAU="$2"; shift 2 ;;
        --max-hull-vertices) K="$2"; shift 2 ;;
        --max-hulls) N="$2"; shift 2 ;;
        --models) MODELS="$2"; shift 2 ;;
        --samples) SAMPLES="$2"; shift 2 ;;
        --peers) PEERS="$2"; shift 2 ;;
        --out) OUTROOT="$2"; shift 2 ;;
        --acd) ACD="$2"; shift 2 ;;
        --table-only) TABLE_ONLY=1; shift ;;
        -h|--help) usage; exit 0 ;;
        *) echo "simulator_corpus: unknown option $1" >&2; usage >&2; exit 2 ;;
    esac
done
[[ -x "$ACD" ]] || { echo "simulator_corpus: $ACD not found; run scripts/setup.sh first" >&2; exit 1; }
PY=/usr/bin/python3
[[ -x "$PY" ]] || PY=python3

failed=0
for model in $MODELS; do
    (( TABLE_ONLY )) && break
    mesh="data/meshes/$model.off"
    [[ -f "$mesh" ]] || { echo "simulator_corpus: $mesh not found (scripts/fetch_corpus.sh)" >&2; failed=1; continue; }
    dir="$OUTROOT/$model"
    rm -rf "$dir"
    mkdir -p "$dir"
    for variant in exact capped; do
        extra=()
        [[ "$variant" == capped ]] && extra=(--max-hull-vertices "$K" --max-hulls "$N")
        echo "[bench] $model τ=$TAU $variant" >&2
        start=$(date +%s.%N)
        rc=0
        "$ACD" decompose "$mesh" -t "$TAU" "${extra[@]}" -o "$dir/$variant" -q >"$dir/$variant.stdout" 2>"$dir/$variant.stderr" || rc=$?
        end=$(date +%s.%N)
        awk -v a="$start" -v b="$end" 'BEGIN { printf "%.3f\n", b - a }' >"$dir/$variant.seconds"
        if (( rc != 0 && rc != 4 )); then
            echo "[bench]   FAILED ($rc, see $dir/$variant.stderr)" >&2
            failed=1
            continue
        fi
        # An open model has no inside to measure against.
        if "$ACD" evaluate "$mesh" "$dir/$variant/hulls.obj" --json --samples "$SAMPLES" >"$dir/$variant.eval.json" 2>"$dir/$variant.eval.stderr"; then
            :
        else
            rm -f "$dir/$variant.eval.json"
        fi
    done
done

"$PY" - "$OUTROOT" "$TAU" "$K" "$N" "$PEERS" $MODELS <<'EOF' || failed=1
import json, os, re, sys
root, tau, K, N, peers = sys.argv[1], float(sys.argv[2]), int(sys.argv[3]), int(sys.argv[4]), sys.argv[5]
models = sys.argv[6:]
vhacd = {}   # V-HACD at its defaults, as bench/compare_peers.sh ran and scored it
for m in sys.argv[6:]:
    try:
        ev = json.load(open(os.path.join(peers, m, 'vhacd-default', 'eval.json')))
        run = json.load(open(os.path.join(peers, m, 'vhacd-default', 'run.json')))
        vhacd[m] = '%d / %.3f / %.2f / %.3f / %.1f' % (ev['hulls'], ev['iou'], 100 * ev['misclassified_share'],
                                                   max(ev['hull_outside_max'], ev['model_to_hulls_max']), run['seconds'])
    except (OSError, ValueError, KeyError):
        pass
def load(path):
    try:
        with open(path) as f:
            return json.load(f)
    except Exception:
        return None
bad = False
print(f"| model | hulls (uncapped) | most vertices per hull | concavity reached (τ {tau:g}) | IoU uncapped | IoU capped | added volume % | model uncovered, max | hulls stick out, max | s | V-HACD default (64): hulls / IoU / err % / excess / s |")
print("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---|")
for m in models:
    d = os.path.join(root, m)
    rep = load(os.path.join(d, 'capped', 'report.json'))
    exact = load(os.path.join(d, 'exact', 'report.json'))
    ev = load(os.path.join(d, 'capped.eval.json'))
    eve = load(os.path.join(d, 'exact.eval.json'))
    if rep is None:
        print(f"| {m} | FAILED | | | | | | | | | {vhacd.get(m, '')} |")
        bad = True
        continue
    comps = rep['components']
    most = max(c['hull_vertices'] for c in comps)
    n = len(comps)
    if most > K or n > N:
        bad = True
    hb = rep.get('hull_budget', {})
    reached = hb.get('max_concavity', rep['totals']['max_concavity'])
    note = ' (above τ)' if reached > tau else ''
    cap = rep.get('hull_vertex_cap', {})
    added = 100.0 * cap.get('added_relative', 0.0)
    before = len(exact['components']) if exact else '?'
    secs = open(os.path.join(d, 'capped.seconds')).read().strip()
    try:
        secs = f"{float(secs):.1f}"
    except ValueError:
        pass
    fmt = lambda x, p: ('n/a' if x is None else f"{x:.{p}f}")
    iou = ev['iou'] if ev else None
    ioue = eve['iou'] if eve else None
    unc = ev['model_to_hulls_max'] if ev else None
    out = ev['hull_outside_max'] if ev else None
    if unc is not None and unc > 0:
        bad = True
    print(f"| {m} | {n} ({before}) | {most} | {reached:.4f}{note} | {fmt(ioue, 3)} | {fmt(iou, 3)} | {added:.1f} | {fmt(unc, 4)} | {fmt(out, 4)} | {secs} | {vhacd.get(m, '')} |")
sys.exit(1 if bad else 0)
EOF
exit $failed

#!/usr/bin/env bash
# Check that a change left the decomposition untouched: decompose the twelve corpus models at
# τ = 0.05 (or --tau) with a build's acd and compare the output byte by byte with a reference folder.
#
#   bench/same_output.sh --acd BUILD/bin/acd --out DIR [--ref REFDIR] [--tau T] [--threads N] [--models "..."]
#
#   --acd PATH     the CLI to run (default: build/bin/acd)
#   --out DIR      where the runs write (DIR/MODEL/: component_NNN.off, hulls.obj, report.json)
#   --ref REFDIR   a folder written the same way by the build before the change; without it the
#                  script only writes DIR (use that to make the reference)
#   --tau T        the tolerance (default 0.05)
#   --threads N    passed to acd decompose (default: acd's own default)
#   --models LIST  corpus model names, files data/meshes/NAME.off (default: the 12 of run_corpus.sh)
#
# report.json is compared without its timings: the "timing" section and every "seconds" field are
# removed (normalised copy: report.stable.json). Every other file is compared as written.
# Exits 0 when all files match, 1 on a difference or a missing file, 2 on a usage error.
set -euo pipefail

ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$ROOT"

ACD="build/bin/acd"
OUT=""
REF=""
THREADS=()
MODELS="elephant armadillo bunny00 camel cow dino homer handle knot eight mushroom ChineseDragon-10kv"
TAU=0.05

usage() { sed -n '2,17p' "$0" | sed 's/^# \{0,1\}//'; }
while [[ $# -gt 0 ]]; do
    case "$1" in
        --acd) ACD="$2"; shift 2 ;;
        --out) OUT="$2"; shift 2 ;;
        --ref) REF="$2"; shift 2 ;;
        --threads) THREADS=(--threads "$2"); shift 2 ;;
        --tau) TAU="$2"; shift 2 ;;
        --models) MODELS="$2"; shift 2 ;;
        -h|--help) usage; exit 0 ;;
        *) echo "same_output: unknown option $1" >&2; usage >&2; exit 2 ;;
    esac
done
[[ -n "$OUT" ]] || { echo "same_output: --out DIR is required" >&2; usage >&2; exit 2; }
[[ -x "$ACD" ]] || { echo "same_output: $ACD not found" >&2; exit 2; }

# The report without what depends on the machine's speed.
stable_report() {
    /usr/bin/python3 - "$1" "$2" <<'PY'
import json, sys
def strip(v):
    if isinstance(v, dict):
        return {k: strip(x) for k, x in v.items() if k != "timing" and k != "seconds" and not k.endswith("_seconds")}
    if isinstance(v, list):
        return [strip(x) for x in v]
    return v
with open(sys.argv[1]) as f:
    report = json.load(f)
with open(sys.argv[2], "w") as f:
    json.dump(strip(report), f, indent=2, sort_keys=False)
    f.write("\n")
PY
}

failed=0
for model in $MODELS; do
    mesh="data/meshes/$model.off"
    [[ -f "$mesh" ]] || { echo "same_output: $mesh not found (scripts/fetch_corpus.sh)" >&2; exit 2; }
    dir="$OUT/$model"
    rm -rf "$dir"
    mkdir -p "$dir"
    rc=0
    "$ACD" decompose "$mesh" -t "$TAU" -o "$dir" --quiet "${THREADS[@]}" >"$dir/../$model.stdout" 2>"$dir/../$model.stderr" || rc=$?
    # 4: finished with some component above tau; 8: a hull stands off the model beyond tau (cow at
    # 0.0175, through its wrap). Both are outcomes to compare; anything else but 0 is a failure.
    if (( rc != 0 && rc != 4 && rc != 8 )); then
        echo "same_output: $model: acd exited $rc (see $OUT/$model.stderr)" >&2
        failed=1
        continue
    fi
    echo "$rc" >"$OUT/$model.exit"
    stable_report "$dir/report.json" "$dir/report.stable.json"
done

if [[ -z "$REF" ]]; then
    echo "same_output: wrote $OUT (no --ref given: nothing compared)"
    exit "$failed"
fi

for model in $MODELS; do
    ref="$REF/$model"
    dir="$OUT/$model"
    [[ -d "$ref" ]] || { echo "same_output: $ref missing" >&2; failed=1; continue; }
    cmp -s "$REF/$model.exit" "$OUT/$model.exit" || { echo "DIFF $model: exit code"; failed=1; }
    # Every file of either side, except the raw report (compared through its stable copy).
    files=$( { ls "$ref"; ls "$dir" 2>/dev/null; } | sort -u | grep -vx report.json || true)
    n=0
    for f in $files; do
        if [[ ! -f "$ref/$f" || ! -f "$dir/$f" ]]; then
            echo "DIFF $model/$f: only on one side"; failed=1
        elif ! cmp -s "$ref/$f" "$dir/$f"; then
            echo "DIFF $model/$f"; failed=1
        fi
        n=$((n + 1))
    done
    echo "[same_output] $model: $n files compared"
done
if (( failed )); then
    echo "same_output: DIFFERENT from $REF"
else
    echo "same_output: identical to $REF"
fi
exit "$failed"

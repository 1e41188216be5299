#!/usr/bin/env bash
# Throughput of acd batch over the whole corpus (data/meshes/*.off), in meshes per minute:
# the local batch with 1 and 2 jobs, and the Dask batch (python3 -m acd.batch) on a LocalCluster
# of 1 and 2 worker processes. Every run starts with an empty cache (but the one that shows the
# cache: the 2-job batch run again); each mesh runs with one thread.
#
#   bench/batch_throughput.sh [--tau 0.2] [--time-limit 120] [--max-kb N] [--acd build/bin/acd] [--out out/bench-batch]
#
# --max-kb N keeps only the corpus files of at most N KiB (a manifest in --out), for a shorter run.
#
# Prints a Markdown table (configuration, meshes, ok / unresolved / failed, wall seconds,
# meshes per minute) on stdout; the runs' outputs stay in --out.
set -euo pipefail

ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$ROOT"
TAU=0.2
LIMIT=120
ACD=build/bin/acd
OUT=out/bench-batch
MAXKB=
while [[ $# -gt 0 ]]; do
    case "$1" in
        --tau) TAU="$2"; shift 2 ;;
        --time-limit) LIMIT="$2"; shift 2 ;;
        --max-kb) MAXKB="$2"; shift 2 ;;
        --acd) ACD="$2"; shift 2 ;;
        --out) OUT="$2"; shift 2 ;;
        *) sed -n '2,12p' "$0" | sed 's/^# \{0,1\}//'; exit 1 ;;
    esac
done
ACD="$(realpath "$ACD")"
# The package as staged by the build, else the sources.
PYTHONPATH="$ROOT/build/python"
[[ -f "$PYTHONPATH/acd/batch.py" ]] || PYTHONPATH="$ROOT/python"
export PYTHONPATH

row() {  # NAME OUTDIR SECONDS
    local n ok un failed
    n=$(wc -l < "$2/batch.jsonl")
    ok=$(jq -r 'select(.status == "ok") | .name' "$2/batch.jsonl" | wc -l)
    un=$(jq -r 'select(.status == "unresolved") | .name' "$2/batch.jsonl" | wc -l)
    failed=$((n - ok - un))
    awk -v name="$1" -v n="$n" -v ok="$ok" -v un="$un" -v f="$failed" -v s="$3" \
        'BEGIN { printf "| %s | %d | %d / %d / %d | %.1f | %.1f |\n", name, n, ok, un, f, s, 60 * n / s }'
}

run() {  # NAME OUTDIR COMMAND...
    local name="$1" dir="$2"; shift 2
    [[ "$name" == *cache* ]] || rm -rf "$dir"
    echo "[bench] $name" >&2
    local start end
    start=$(date +%s.%N)
    "$@" >"$dir.log" 2>&1 || true   # some corpus meshes are refused: exit 7 is expected
    end=$(date +%s.%N)
    row "$name" "$dir" "$(awk -v a="$start" -v b="$end" 'BEGIN { print b - a }')"
}

mkdir -p "$OUT"
echo "| configuration | meshes | ok / unresolved / failed | wall s | meshes/min |"
echo "|---|---:|---|---:|---:|"
INPUT=data/meshes
if [[ -n "$MAXKB" ]]; then
    INPUT="$OUT/meshes-under-${MAXKB}k.txt"
    find "$ROOT/data/meshes" -name '*.off' -size -"$((MAXKB + 1))"k | sort > "$INPUT"
fi
COMMON=("$INPUT" -t "$TAU" --threads 1 --time-limit "$LIMIT" -q)
run "local, 1 job" "$OUT/local1" "$ACD" batch "${COMMON[@]}" --jobs 1 -o "$OUT/local1"
run "local, 2 jobs" "$OUT/local2" "$ACD" batch "${COMMON[@]}" --jobs 2 -o "$OUT/local2"
# The same batch again: everything from the cache.
cp -r "$OUT/local2" "$OUT/local2-again"
run "local, 2 jobs, second run (cache)" "$OUT/local2-again" "$ACD" batch "${COMMON[@]}" --jobs 2 -o "$OUT/local2-again"
run "Dask LocalCluster, 1 worker" "$OUT/dask1" /usr/bin/python3 -m acd.batch "${COMMON[@]}" --acd "$ACD" \
    --scheduler local:1 -o "$OUT/dask1"
run "Dask LocalCluster, 2 workers" "$OUT/dask2" /usr/bin/python3 -m acd.batch "${COMMON[@]}" --acd "$ACD" \
    --scheduler local:2 -o "$OUT/dask2"

#!/usr/bin/env bash
# Surface ACD over corpus models: one Markdown row per model, tolerance and grouping setting.
#
#   bench/surface_acd.sh [--taus "0.2 0.02"] [--models "mushroom elephant"] [--no-grouping]
#                        [--repeat N] [--out DIR] [--acd PATH]
#
#   --taus         concavity tolerances τ (default: 0.2 0.02)
#   --models       corpus names, files data/meshes/NAME.off (default: the four open models
#                  and three closed ones)
#   --no-grouping  also run every case with --no-grouping (planes through the notch only)
#   --repeat N     run each case N times; the time is the median of report.json's total_seconds
#   --out DIR      where the runs write (default: out/bench-surface)
#   --acd PATH     the CLI (default: build/bin/acd)
#
# Each run is `ACD decompose data/meshes/MODEL.off --surface -t TAU -q -o DIR`; the row comes from
# DIR/report.json. The baseline, run once per model in the same run, is the exact convex surface
# decomposition (`--exact --surface`). Progress goes to stderr, the table to stdout. Exit 1 if a
# run failed.
set -euo pipefail

ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$ROOT"

TAUS="0.2 0.02"
MODELS="mushroom ChineseDragon-10kv elephant-with-holes mesh_with_border elephant bunny00 knot"
BOTH=0
REPEAT=1
OUTROOT="out/bench-surface"
ACD="build/bin/acd"

usage() { sed -n '2,19p' "$0" | sed 's/^# \{0,1\}//'; }
while [[ $# -gt 0 ]]; do
    case "$1" in
        --taus) TAUS="$2"; shift 2 ;;
        --models) MODELS="$2"; shift 2 ;;
        --no-grouping) BOTH=1; shift ;;
        --repeat) REPEAT="$2"; shift 2 ;;
        --out) OUTROOT="$2"; shift 2 ;;
        --acd) ACD="$2"; shift 2 ;;
        -h|--help) usage; exit 0 ;;
        *) echo "surface_acd: unknown option $1" >&2; usage >&2; exit 2 ;;
    esac
done
[[ "$REPEAT" =~ ^[1-9][0-9]*$ ]] || { echo "surface_acd: --repeat needs a positive integer" >&2; exit 2; }
command -v jq >/dev/null 2>&1 || { echo "surface_acd: jq missing (apt-get install jq)" >&2; exit 1; }
[[ -x "$ACD" ]] || { echo "surface_acd: $ACD not found; run scripts/setup.sh first" >&2; exit 1; }

mkdir -p "$OUTROOT"
VARIANTS=(on)
(( BOTH )) && VARIANTS=(on off)
median() { sort -g | awk '{a[NR]=$1} END {if (NR==0) exit; if (NR%2) print a[(NR+1)/2]; else print (a[NR/2]+a[NR/2+1])/2}'; }

echo "| model | faces | boundary edges | concave hull vertices | τ | grouping | patches | % of surface ECD patches | max concavity | splits (global cut / plane / geodesic) | merges | patches.obj bytes | time s |"
echo "|---|---:|---:|---:|---:|---|---:|---:|---:|---|---:|---:|---:|"
failed=0
for model in $MODELS; do
    mesh="data/meshes/$model.off"
    # The baseline, in the same run: the exact convex surface decomposition (--exact --surface).
    ecd=0
    if "$ACD" decompose "$mesh" --exact --surface -q -o "$OUTROOT/$model-ecd" 2>"$OUTROOT/$model-ecd.log"; then
        ecd=$(jq '.totals.components' "$OUTROOT/$model-ecd/report.json")
    fi
    for tau in $TAUS; do
        for grouping in "${VARIANTS[@]}"; do
            dir="$OUTROOT/$model-$tau-$grouping"
            extra=()
            [[ "$grouping" == off ]] && extra=(--no-grouping)
            times=()
            code=0
            for ((r = 0; r < REPEAT; ++r)); do
                [[ -t 2 ]] && echo "surface_acd: $model tau $tau grouping $grouping run $((r + 1))" >&2
                rm -rf "$dir"
                code=0
                "$ACD" decompose "$mesh" --surface -t "$tau" "${extra[@]}" -q -o "$dir" 2>"$dir.log" || code=$?
                [[ $code -eq 0 || $code -eq 4 ]] || break
                times+=("$(jq '.timing.total_seconds' "$dir/report.json")")
            done
            if [[ $code -ne 0 && $code -ne 4 ]]; then
                echo "| $model | | | | $tau | $grouping | FAILED (exit $code: $(tail -1 "$dir.log")) | | | | | | |"
                failed=1
                continue
            fi
            t=$(printf '%s\n' "${times[@]}" | median)
            jq -r --arg model "$model" --arg tau "$tau" --arg g "$grouping" --arg t "$t" --argjson ecd "$ecd" \
                '"| \($model) | \(.input.faces) | \(.input.boundary_edges) | \(.input.concave_hull_vertices) | \($tau) | \($g) | \(.totals.components)\(if .totals.unresolved > 0 then " (\(.totals.unresolved) unresolved)" else "" end) | \(if $ecd > 0 then (.totals.components * 10000 / $ecd | round / 100 | tostring) + " % of \($ecd)" else "n/a" end) | \(.totals.max_concavity * 1000 | round / 1000) | \(.totals.splits) (\(.totals.global_cut_splits) / \(.totals.plane_splits) / \(.totals.geodesic_splits)) | \(.totals.merges) | \(.totals.output_bytes) | \($t | tonumber * 100 | round / 100) |"' \
                "$dir/report.json"
        done
    done
done
exit $failed

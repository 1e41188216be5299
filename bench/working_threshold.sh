#!/usr/bin/env bash
# Where does the working mesh start to pay? Decomposes closed meshes from the CGAL demo data that
# are not among the ten corpus models, each at full resolution (--working-share 0) and through the
# working mesh (--working-from-faces 0), alternating, and prints a Markdown table sorted by face
# count: medians of the wall times (spread in brackets) and the parts of each. This is what chose
# the default of --working-from-faces (docs/ALGORITHM.md, "The working mesh").
#
#   bench/working_threshold.sh [--models "femur bull"] [--tau 0.05] [--repeat 3] [--out DIR] [--acd PATH]
set -euo pipefail

ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$ROOT"

MODELS="anchor_dense femur bull fandisk blade turbine bear_bis bear fandisk_large refined_elephant"
TAU=0.05
REPEAT=3
OUT="out/working_threshold"
ACD="build/bin/acd"

usage() { sed -n '2,8p' "$0" | sed 's/^# \{0,1\}//'; }
while [[ $# -gt 0 ]]; do
    case "$1" in
        --models) MODELS="$2"; shift 2 ;;
        --tau) TAU="$2"; shift 2 ;;
        --repeat) REPEAT="$2"; shift 2 ;;
        --out) OUT="$2"; shift 2 ;;
        --acd) ACD="$2"; shift 2 ;;
        -h|--help) usage; exit 0 ;;
        *) echo "working_threshold: unknown option $1" >&2; usage >&2; exit 2 ;;
    esac
done
[[ -x "$ACD" ]] || { echo "working_threshold: $ACD not found; build the acd_cli target first" >&2; exit 1; }
command -v jq >/dev/null || { echo "working_threshold: needs jq" >&2; exit 1; }
mkdir -p "$OUT"

# median and spread of a list of numbers, as "M (LO-HI)"
summary() { tr ' ' '\n' | sort -g | awk '{v[NR]=$1} END {printf "%.2f (%.2f-%.2f)", v[int((NR+1)/2)], v[1], v[NR]}'; }

rows=()
for m in $MODELS; do
    mesh="data/meshes/$m.off"
    [[ -f "$mesh" ]] || { echo "working_threshold: $mesh missing (scripts/fetch_corpus.sh)" >&2; exit 1; }
    full=() working=()
    for ((r = 0; r < REPEAT; r++)); do
        for mode in full working; do
            flags=(--working-share 0)
            [[ $mode == working ]] && flags=(--working-share 0.1 --working-from-faces 0)
            start=$(date +%s.%N)
            "$ACD" decompose "$mesh" -t "$TAU" "${flags[@]}" -q -o "$OUT/$m-$mode" >/dev/null 2>&1 || true
            t=$(awk -v a="$start" -v b="$(date +%s.%N)" 'BEGIN { printf "%.3f", b - a }')
            if [[ $mode == full ]]; then full+=("$t"); else working+=("$t"); fi
        done
    done
    faces=$(jq '.input.faces' "$OUT/$m-full/report.json")
    parts_full=$(jq '.components | length' "$OUT/$m-full/report.json")
    parts_working=$(jq '.components | length' "$OUT/$m-working/report.json")
    rows+=("$faces|$m|$(echo "${full[*]}" | summary)|$(echo "${working[*]}" | summary)|$parts_full|$parts_working")
done

echo "| model | faces | full resolution, s | working mesh, s | parts, full | parts, working |"
echo "|---|---:|---:|---:|---:|---:|"
printf '%s\n' "${rows[@]}" | sort -t'|' -k1,1n | awk -F'|' '{printf "| %s | %s | %s | %s | %s | %s |\n", $2, $1, $3, $4, $5, $6}'

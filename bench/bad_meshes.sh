#!/usr/bin/env bash
# The generated bad-mesh set (tests/bad_meshes.hpp) through the CLI: each case is written by
# build/bin/bad_meshes, decomposed by build/bin/acd, and must end as the set says: decomposed
# from the input, decomposed through the wrap, or refused with a one-line reason. A decomposition
# whose hulls do not keep tau must say so (exit 8), as a wrap of a soup of sheets may.
#
#   bench/bad_meshes.sh [--tau 0.1] [--out DIR]
#
# Prints a Markdown table (case, problem, expected, exit, outcome, first stderr line) and exits 1
# on any mismatch.
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$ROOT"
TAU=0.1
OUT="out/bad_meshes"
while [[ $# -gt 0 ]]; do
    case "$1" in
        --tau) TAU="$2"; shift 2 ;;
        --out) OUT="$2"; shift 2 ;;
        -h|--help) sed -n '2,9p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
        *) echo "bad_meshes: unknown option $1" >&2; exit 2 ;;
    esac
done
[[ -x build/bin/bad_meshes && -x build/bin/acd ]] || { echo "bad_meshes: build acd_cli and bad_meshes first" >&2; exit 1; }
rm -rf "$OUT"; mkdir -p "$OUT/meshes"
build/bin/bad_meshes "$OUT/meshes"
failed=0
echo "| case | problem | expected | exit | outcome | what acd said (first line) |"
echo "|---|---|---|---:|---|---|"
while IFS=$'\t' read -r name expected problem; do
    rc=0
    build/bin/acd decompose "$OUT/meshes/$name.off" -t "$TAU" -o "$OUT/$name" --quiet \
        >"$OUT/$name.stdout" 2>"$OUT/$name.stderr" || rc=$?
    outcome="refused"
    # 0: decomposed; 8: decomposed, but a hull stands beyond tau, which acd said (all files written).
    if (( rc == 0 || rc == 8 )); then
        outcome=$(jq -r 'if .input.wrap.used then "wrap" else "input" end' "$OUT/$name/report.json")
    fi
    said=$(head -n 1 "$OUT/$name.stderr" | sed "s|$OUT/meshes/||; s/|/\\\\|/g")
    mark=""
    if [[ "$outcome" != "$expected" ]] || (( rc != 0 && rc != 2 && rc != 8 )); then mark=" **MISMATCH**"; failed=1; fi
    echo "| $name | $problem | $expected | $rc | $outcome$mark | ${said:-} |"
done <"$OUT/meshes/cases.tsv"
exit $failed

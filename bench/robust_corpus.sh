#!/usr/bin/env bash
# Every corpus model must decompose with exit 0 and no unresolved component: the repairs and the
# wrap (docs/ERRORS.md) take what the plain decomposition left above tau.
#
#   bench/robust_corpus.sh [--taus "0.05"] [--models "cow camel"] [--out DIR] [--acd PATH] [-- EXTRA...]
#
# Prints a Markdown table: exit code, components, unresolved, whether (and what of) the model was
# wrapped, the wrap's Hausdorff distance to the input, and the repair, wrap and total wall times
# from report.json. Exits 1 when any run does not exit 0 or leaves a component unresolved.
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$ROOT"
TAUS="0.05"
MODELS="elephant armadillo bunny00 camel cow dino homer handle knot eight mushroom ChineseDragon-10kv"
OUTROOT="out/robust"
ACD="build/bin/acd"
EXTRA=()
while [[ $# -gt 0 ]]; do
    case "$1" in
        --taus) TAUS="$2"; shift 2 ;;
        --models) MODELS="$2"; shift 2 ;;
        --out) OUTROOT="$2"; shift 2 ;;
        --acd) ACD="$2"; shift 2 ;;
        --) shift; EXTRA=("$@"); break ;;
        -h|--help) sed -n '2,10p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
        *) echo "robust_corpus: unknown option $1" >&2; exit 2 ;;
    esac
done
command -v jq >/dev/null 2>&1 || { echo "robust_corpus: jq missing" >&2; exit 1; }
[[ -x "$ACD" ]] || { echo "robust_corpus: $ACD not found; run scripts/setup.sh first" >&2; exit 1; }

failed=0
echo "| model | τ | exit | components | unresolved | wrapped | wrap Hausdorff | repair (s) | wrap (s) | total (s) |"
echo "|---|---:|---:|---:|---:|---|---:|---:|---:|---:|"
for model in $MODELS; do
    for tau in $TAUS; do
        out="$OUTROOT/$model-t$tau"
        rm -rf "$out"; mkdir -p "$out"
        echo "[robust] $model τ=$tau" >&2
        rc=0
        "$ACD" decompose "data/meshes/$model.off" -t "$tau" -o "$out" --quiet "${EXTRA[@]}" \
            >"$out/stdout.txt" 2>"$out/stderr.txt" || rc=$?
        if [[ ! -f "$out/report.json" ]]; then
            echo "| $model | $tau | $rc | | | | | | | |"
            echo "[robust]   FAILED: $(head -c 300 "$out/stderr.txt")" >&2
            failed=1; continue
        fi
        jq -r --arg m "$model" --arg t "$tau" --arg rc "$rc" '
            def f: . * 1000 | round / 1000;
            "| \($m) | \($t) | \($rc) | \(.components | length) | \(.totals.unresolved) | " +
            (if .input.wrap.used then "yes: \(.input.wrap.wrapped_pieces) piece(s)" else "no" end) + " | " +
            (if .input.wrap.used then (.input.wrap.hausdorff | . * 10000 | round / 10000 | tostring) else "" end) + " | " +
            "\(.timing.repair_seconds | f) | \(.timing.wrap_seconds | f) | \(.timing.total_seconds | f) |"' "$out/report.json"
        unresolved=$(jq -r '.totals.unresolved' "$out/report.json")
        if (( rc != 0 || unresolved != 0 )); then failed=1; fi
    done
done
exit $failed

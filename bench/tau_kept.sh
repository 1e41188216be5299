#!/usr/bin/env bash
# Is tau kept where users measure it? Decomposes each closed corpus model at each tau and
# measures with `acd evaluate` how far the hulls stick out of the model (sampled maximum,
# normalised units). Prints a Markdown table: parts and stick-out per model and tau, the
# stick-out as a multiple of tau; exits 1 when some hull sticks out by more than tau.
#
#   bench/tau_kept.sh [--models "elephant eight"] [--taus "0.2 0.1 0.05 0.02"]
#                     [--samples N] [--out DIR] [--acd PATH] [-- EXTRA ACD OPTIONS]
#
#   --models   default: the 10 closed corpus models      --taus  default: 0.2 0.1 0.05 0.02
#   --samples  surface samples of acd evaluate (default 2000000)
#   --out      where the decompositions go (default out/tau_kept)
set -euo pipefail

ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$ROOT"

MODELS="armadillo bunny00 camel cow dino eight elephant handle homer knot"
TAUS="0.2 0.1 0.05 0.02"
SAMPLES=2000000
OUT="out/tau_kept"
ACD="build/bin/acd"
EXTRA=()

usage() { sed -n '2,12p' "$0" | sed 's/^# \{0,1\}//'; }
while [[ $# -gt 0 ]]; do
    case "$1" in
        --models) MODELS="$2"; shift 2 ;;
        --taus) TAUS="$2"; shift 2 ;;
        --samples) SAMPLES="$2"; shift 2 ;;
        --out) OUT="$2"; shift 2 ;;
        --acd) ACD="$2"; shift 2 ;;
        --) shift; EXTRA=("$@"); break ;;
        -h|--help) usage; exit 0 ;;
        *) echo "tau_kept: unknown option $1" >&2; usage >&2; exit 2 ;;
    esac
done
[[ -x "$ACD" ]] || { echo "tau_kept: $ACD not found; build the acd_cli target first" >&2; exit 1; }
command -v jq >/dev/null || { echo "tau_kept: needs jq" >&2; exit 1; }

header="| model |"
rule="|---|"
for tau in $TAUS; do header+=" parts τ=$tau | stick-out τ=$tau |"; rule+="---:|---:|"; done
echo "$header"
echo "$rule"
failed=0
for model in $MODELS; do
    src="data/meshes/$model.off"
    [[ -f "$src" ]] || { echo "tau_kept: $src not found (scripts/fetch_corpus.sh)" >&2; exit 1; }
    row="| $model |"
    for tau in $TAUS; do
        dir="$OUT/$model/t$tau"
        rm -rf "$dir"
        rc=0
        "$ACD" decompose "$src" -t "$tau" -o "$dir" -q "${EXTRA[@]}" 2>"$OUT.stderr" || rc=$?
        if (( rc != 0 && rc != 4 && rc != 8 )); then
            echo "tau_kept: $model at tau $tau: decompose exit $rc" >&2; failed=1; row+=" – | – |"; continue
        fi
        parts=$(jq '.components | length' "$dir/report.json")
        out=$("$ACD" evaluate "$src" "$dir/hulls.obj" --json --samples 1 --surface-samples "$SAMPLES" | jq '.hull_outside_max')
        ratio=$(awk -v o="$out" -v t="$tau" 'BEGIN { printf "%.2f", o / t }')
        flag=""
        if awk -v o="$out" -v t="$tau" 'BEGIN { exit !(o > t) }'; then flag=" ✗"; failed=1; fi
        (( rc == 4 )) && flag+=" †"
        row+=" $parts | $(printf '%.4f' "$out") (${ratio}τ)$flag |"
    done
    echo "$row"
done
echo
echo "Stick-out: \`acd evaluate\` hull_outside_max with $SAMPLES surface samples (normalised units); ✗ above tau; † some component unresolved (exit 4)."
exit "$failed"

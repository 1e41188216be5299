#!/usr/bin/env bash
# Error of point location with the ACD hulls, for every corpus model and several tau,
# as a Markdown table on stdout.
#
#   bench/pointloc_errors.sh [--taus "0.2 0.05 0.02"] [--models "elephant camel"]
#                            [--samples 2e6] [--pointloc PATH]
#
# Each case runs `pointloc data/meshes/MODEL.off --tau TAU --samples N --exact-samples N
# --json FILE`: every one of the N points (uniform in the model's bounding box, seed 1) is
# checked against the exact answer, so the rates below are counts over N, with 95 % Wilson
# intervals. Models that pointloc refuses (open meshes) get a row saying why.
set -euo pipefail

ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$ROOT"

TAUS="0.2 0.05 0.02"
MODELS="elephant armadillo bunny00 camel cow dino homer handle knot eight mushroom ChineseDragon-10kv"
SAMPLES="2e6"
POINTLOC="build/bin/pointloc"

usage() { sed -n '2,12p' "$0" | sed 's/^# \{0,1\}//'; }
while [[ $# -gt 0 ]]; do
    case "$1" in
        --taus) TAUS="$2"; shift 2 ;;
        --models) MODELS="$2"; shift 2 ;;
        --samples) SAMPLES="$2"; shift 2 ;;
        --pointloc) POINTLOC="$2"; shift 2 ;;
        -h|--help) usage; exit 0 ;;
        *) echo "pointloc_errors: unknown option $1" >&2; usage >&2; exit 2 ;;
    esac
done
[[ -x "$POINTLOC" ]] || { echo "pointloc_errors: $POINTLOC not found; run scripts/setup.sh first" >&2; exit 1; }

TMP="$(mktemp -d)"
trap 'rm -rf "$TMP"' EXIT

echo "| model | τ | components | model % of box | false inside % | false outside % | error % (95% CI) | error / model volume % | largest contributor (share of false inside) | decomposition s |"
echo "|---|---:|---:|---:|---:|---:|---|---:|---|---:|"
failed=0
for model in $MODELS; do
    for tau in $TAUS; do
        json="$TMP/$model-$tau.json"
        [[ -t 2 ]] && echo "pointloc_errors: $model tau $tau" >&2
        if "$POINTLOC" "data/meshes/$model.off" --tau "$tau" --samples "$SAMPLES" --exact-samples "$SAMPLES" \
               --json "$json" > "$TMP/out.txt" 2> "$TMP/err.txt"; then
            /usr/bin/python3 - "$json" "$model" "$tau" <<'PY'
import json, sys
j = json.load(open(sys.argv[1])); e = j["exact"]; n = e["samples"]
top = e["top_false_inside"]
lead = f"component {top[0]['component']} ({100 * top[0]['share']:.0f} %)" if top else "-"
comps = f"{j['components']}" + (f" ({j['unresolved_components']} unresolved)" if j["unresolved_components"] else "")
print(f"| {sys.argv[2]} | {sys.argv[3]} | {comps} | {100 * e['points_inside'] / n:.2f} "
      f"| {100 * e['false_inside_rate']:.3f} | {100 * e['false_outside_rate']:.4f} "
      f"| {100 * e['error_rate']:.3f} [{100 * e['error_rate_ci95'][0]:.3f}, {100 * e['error_rate_ci95'][1]:.3f}] "
      f"| {100 * e['error_rate_of_inside']:.2f} | {lead} | {j['decomposition_seconds']:.2f} |")
PY
        else
            code=$?
            reason="$(head -n1 "$TMP/err.txt" | sed 's/^pointloc: //; s/|/\\|/g')"
            if [[ $code -eq 2 ]]; then
                echo "| $model | $tau | refused: $reason | | | | | | | |"
            else
                echo "| $model | $tau | FAILED (exit $code): $reason | | | | | | | |"
                failed=1
            fi
        fi
    done
done
exit $failed

#!/usr/bin/env bash
# tetmesh against TetGen on the original model: tets, quality, volume error and time for the
# hull meshes of the solid ACD at several tau, as a Markdown table on stdout.
#   bench/tetmesh_compare.sh [--models "elephant armadillo camel"] [--taus "0.2 0.05"] [--extra "--simplify 32"]
# Needs build/bin/tetmesh (scripts/setup.sh) and the corpus (scripts/fetch_corpus.sh).
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
MODELS="elephant armadillo camel"
TAUS="0.2 0.05"
EXTRA=""
BIN="${TETMESH_BIN:-$ROOT/build/bin/tetmesh}"
while [ $# -gt 0 ]; do
  case "$1" in
    --models) MODELS="$2"; shift 2 ;;
    --taus) TAUS="$2"; shift 2 ;;
    --extra) EXTRA="$2"; shift 2 ;;
    *) echo "unknown option $1" >&2; exit 1 ;;
  esac
done
OUT="$(mktemp -d)"
trap 'rm -rf "$OUT"' EXIT
echo "| model | τ | components | mesh | hulls meshed | tets | vertices | volume error | min dihedral | max dihedral | radius-edge median / max | TetGen s | total s |"
echo "|---|---:|---:|---|---|---:|---:|---:|---:|---:|---:|---:|---:|"
for m in $MODELS; do
  for t in $TAUS; do
    json="$OUT/$m-$t.json"
    # shellcheck disable=SC2086
    if ! "$BIN" "$ROOT/data/meshes/$m.off" -t "$t" --compare --quiet --json "$json" $EXTRA > "$OUT/log" 2>&1; then
      echo "| $m | $t | | failed: $(tail -1 "$OUT/log" | cut -c1-120) | | | | | | | | | |"
      continue
    fi
    /usr/bin/python3 - "$json" "$m" "$t" <<'PY'
import json, sys
j = json.load(open(sys.argv[1])); m, t = sys.argv[2], sys.argv[3]
s = j["seconds"]; total = sum(s.values())
used = "exact" if j.get("simplify", 0) == 0 or j.get("simplify_fallback") else f"at most {j.get('simplify_used')} vertices"
if j.get("simplify_fallback"): used += f" (all budgets <= {j['simplify']} refused)"
def row(name, q, err, tg, tot, comps, hulls):
    print(f"| {m} | {t} | {comps} | {name} | {hulls} | {q['tets']} | {q['vertices']} | {100*err:+.2f}% | {q['min_dihedral_deg']:.2f} | "
          f"{q['max_dihedral_deg']:.2f} | {q['radius_edge']['median']:.2f} / {q['radius_edge']['max']:.3g} | {tg:.2f} | {tot:.2f} |")
row("ACD hulls", j["hull_mesh"], j["volume_error"], s["tetgen"], total, len(j["components"]), used)
o = j.get("original_mesh", {})
if "error" in o:
    print(f"| {m} | {t} | | original: not meshed ({o['error'][:90]}) | | | | | | | | | |")
else:
    row("original", o, o["volume_error"], o["seconds"], o["seconds"], "", "")
PY
  done
done

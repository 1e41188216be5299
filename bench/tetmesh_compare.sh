#!/usr/bin/env bash
# tetmesh against TetGen on the model itself, as the Markdown table of docs/TETMESH.md: for each
# model, tau and mode, the hull mesh (tetmesh's default mesher) beside TetGen's mesh of the
# model's own surface with the same quality switch (coarse: no refinement, `-pQ`; quality:
# `-pq1.5Q`). One run of each; tets and angles do not depend on the machine, times do.
#   bench/tetmesh_compare.sh [--models "elephant knot"] [--taus "0.2 0.1"] [--modes "coarse quality"]
#                            [--quality 1.5] [--extra "--mesher complex"]
# Needs build/bin/tetmesh (scripts/setup.sh) and the corpus (scripts/fetch_corpus.sh).
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
MODELS="armadillo bunny00 camel cow dino eight elephant handle homer knot"  # the ten closed corpus models
TAUS="0.2 0.1"
MODES="coarse quality"
QUALITY=1.5
EXTRA=""
BIN="${TETMESH_BIN:-$ROOT/build/bin/tetmesh}"
while [ $# -gt 0 ]; do
  case "$1" in
    --models) MODELS="$2"; shift 2 ;;
    --taus) TAUS="$2"; shift 2 ;;
    --modes) MODES="$2"; shift 2 ;;
    --quality) QUALITY="$2"; shift 2 ;;
    --extra) EXTRA="$2"; shift 2 ;;
    *) echo "unknown option $1" >&2; exit 1 ;;
  esac
done
OUT="$(mktemp -d)"
trap 'rm -rf "$OUT"' EXIT
for mode in $MODES; do
  case "$mode" in
    coarse) flags="" ; title="Coarse (the default; TetGen on the model without refinement, \`-pQ\`)" ;;
    quality) flags="--quality $QUALITY" ; title="Quality (\`--quality $QUALITY\`; TetGen on the model with \`-pq${QUALITY}Q\`)" ;;
    *) echo "unknown mode $mode (coarse, quality)" >&2; exit 1 ;;
  esac
  echo
  echo "$title:"
  echo
  echo "| model | τ | parts | tets: hulls / model | ratio | min dihedral | max dihedral | tets < 5° | radius-edge median / max | radius-edge > 2 | volume vs model | s: hulls (mesh) / model |"
  echo "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|"
  for m in $MODELS; do
    for t in $TAUS; do
      json="$OUT/$m-$t-$mode.json"
      # shellcheck disable=SC2086
      if ! "$BIN" "$ROOT/data/meshes/$m.off" -t "$t" --compare --quiet --json "$json" $flags $EXTRA > "$OUT/log" 2>&1; then
        echo "| $m | $t | | failed: $(tail -1 "$OUT/log" | cut -c1-120) | | | | | | | | |"
        continue
      fi
      /usr/bin/python3 - "$json" "$m" "$t" <<'PY'
import json, sys
j = json.load(open(sys.argv[1])); m, t = sys.argv[2], sys.argv[3]
h, o, s = j["hull_mesh"], j.get("original_mesh", {}), j["seconds"]
ok = "tets" in o
def pair(a, b, f="{:.2f}"):
    return f.format(a) + " / " + (f.format(b) if ok else "–")
def above2(q):
    hist = q["radius_edge_histogram"]
    return 100.0 * sum(b["tets"] for b in hist if b["upto"] is None or b["upto"] > 2.0) / max(1, q["tets"])
ratio = f"{h['tets'] / o['tets']:.2f}" if ok else "–"
mesh_s = s["tetgen"] + s["refine"] + s.get("coarsen", 0.0)
total = sum(s.values())
print(f"| {m} | {t} | {len(j['components'])} | {pair(h['tets'], o.get('tets', 0), '{}')} | {ratio} | "
      f"{pair(h['min_dihedral_deg'], o.get('min_dihedral_deg', 0))} | {pair(h['max_dihedral_deg'], o.get('max_dihedral_deg', 0), '{:.1f}')} | "
      f"{pair(h['tets_below_5_deg'], o.get('tets_below_5_deg', 0), '{}')} | "
      f"{h['radius_edge']['median']:.2f} / {h['radius_edge']['max']:.2f}" + (f" (model {o['radius_edge']['median']:.2f} / {o['radius_edge']['max']:.3g})" if ok else "") + " | "
      f"{above2(h):.1f}% / " + (f"{above2(o):.1f}%" if ok else "–") + " | "
      f"{100 * j['volume_error']:+.1f}% | {total:.2f} ({mesh_s:.2f}) / " + (f"{o['seconds']:.2f}" if ok else "–") + " |")
if not ok:
    print(f"| | | | model not meshed: {o.get('error', '')[:100]} | | | | | | | | |")
PY
    done
  done
done

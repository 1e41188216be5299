#!/usr/bin/env bash
# The deformation demo's table in docs/TETMESH.md: tetmesh's default mesh of five corpus models
# at tau 0.2 deformed as rigidly as possible (ARAP) with the default motion, and the elephant
# with a turn, without the weight floor, without the coarsening and at --quality 1.5.
#   bench/tetmesh_deform.sh [OUT_DIR]     (default out/tetmesh-deform; about a minute)
# Needs build/bin/tetmesh (scripts/setup.sh) and the corpus (scripts/fetch_corpus.sh).
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
OUT="${1:-$ROOT/out/tetmesh-deform}"
BIN="${TETMESH_BIN:-$ROOT/build/bin/tetmesh}"
mkdir -p "$OUT"
run() {  # name model extra-flags...
  local name="$1" model="$2"
  shift 2
  "$BIN" "$ROOT/data/meshes/$model.off" -t 0.2 --threads 1 -q --deform "$OUT/$name" --json "$OUT/$name.json" "$@" > "$OUT/$name.log"
}
run elephant elephant
run elephant-a30 elephant --deform-angle 30
run elephant-a30-w0 elephant --deform-angle 30 --deform-min-weight 0
run elephant-refined elephant --no-coarsen
run elephant-q15 elephant --quality 1.5
for m in armadillo camel bunny00 knot; do run "$m" "$m"; done
run bunny00-w0 bunny00 --deform-min-weight 0

echo "| run | tets | tet vertices | surface vertices (outside, farthest) | handle / anchor | iterations | energy first → last | inverted tets ARAP (linear) | surface volume change ARAP (linear) | surface self-intersections before → after | ARAP s | surface on handle off by |"
echo "|---|---|---|---|---|---|---|---|---|---|---|---|"
for name in elephant elephant-a30 elephant-a30-w0 elephant-refined elephant-q15 armadillo camel bunny00 bunny00-w0 knot; do
  /usr/bin/python3 - "$OUT/$name.json" "$name" <<'PY'
import json, sys
j = json.load(open(sys.argv[1])); name = sys.argv[2]
labels = {"elephant-a30": "elephant, `--deform-angle 30`",
          "elephant-a30-w0": "elephant, `--deform-angle 30 --deform-min-weight 0`",
          "elephant-refined": "elephant, `--no-coarsen`",
          "elephant-q15": "elephant, `--quality 1.5`",
          "bunny00-w0": "bunny00, `--deform-min-weight 0`"}
h, d = j["hull_mesh"], j["deformation"]
a, e = d["arap"], d["embedding"]
sv = d["surface_volume"]
def change(x): return f"{100 * (x / sv['rest'] - 1):+.2f}%"
iters = f"{a['iterations']}" + ("" if a["converged"] else " (limit)")
print(f"| {labels.get(name, name)} | {h['tets']} | {h['vertices']} | {e['vertices']} ({e['outside']}, {e['max_outside_distance']:.2g}) "
      f"| {d['handle']} / {d['anchor']} | {iters} | {a['energy'][0]:.4g} → {a['energy'][-1]:.4g} "
      f"| {a['inverted_tets']} ({a['linear_inverted_tets']}) | {change(sv['after'])} ({change(sv['linear'])}) "
      f"| {d['self_intersections']['before']} → {d['self_intersections']['after']} | {a['factor_seconds'] + a['solve_seconds']:.2f} "
      f"| {a['surface_handle_error']:.0e} |")
PY
done

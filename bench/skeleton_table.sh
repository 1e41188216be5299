#!/usr/bin/env bash
# Skeletons under deformation (paper, Section 7, Figure 21): three corpus models, each with an
# ARAP limb bend, a rigid motion with non-uniform scaling, and a rigid motion alone (a control:
# the ACD skeleton should not change at all); ACD skeleton and CGAL's
# mean-curvature-flow skeleton (three runs per mesh, since its size varies run to run).
# Writes OUT/<model>/ (skeletons, deformed meshes, report.json) and OUT/table.md.
#
#   bench/skeleton_table.sh [BUILD_DIR (default build)] [OUT (default out/skeleton)]
set -euo pipefail
ROOT="$(cd "$(dirname "$0")/.." && pwd)"
BUILD="${1:-$ROOT/build}"
OUT="${2:-$ROOT/out/skeleton}"
BIN="$BUILD/bin/skeleton"
[[ -x "$BIN" ]] || { echo "skeleton_table: $BIN not built" >&2; exit 1; }
mkdir -p "$OUT"

run() {
    local model="$1"
    shift
    local code=0
    /usr/bin/time -f "$model: %e s wall, %M KiB" "$BIN" "$ROOT/data/meshes/$model.off" --tau 0.1 --mcf-runs 3 \
        --tubes 0.004 -o "$OUT/$model" "$@" >"$OUT/$model.txt" || code=$?
    # 4: finished, but some component is still above tau (reported in report.json): a result.
    [[ $code == 0 || $code == 4 ]] || { echo "skeleton_table: $model failed ($code)" >&2; exit 1; }
    cat "$OUT/$model.txt"
}

RIGID=affine:30,-20,45:1,1,1:0.1,0.2,0
run elephant --deform bend:+x:z:-40 --deform affine:20,35,-10:1.3,1,0.8:0.2,0,0 --deform $RIGID
run camel --deform bend:+y:x:35 --deform affine:-15,0,30:1,1.25,0.85:0,0.1,0 --deform $RIGID
run armadillo --deform bend:+x:z:40 --deform affine:0,60,10:0.8,1.2,1:5,0,0 --deform $RIGID

/usr/bin/python3 - "$OUT" elephant camel armadillo >"$OUT/table.md" <<'PYEOF'
import json, sys
out, models = sys.argv[1], sys.argv[2:]

def dist(d):
    if d is None:
        return "-"
    if d["exact"] or d["lower_bound"] == d["distance"]:
        return "%d" % d["distance"]
    return "%d–%d" % (d["lower_bound"], d["distance"])

def counts(s):
    return "%d / %d" % (s["nodes"], s["nodes_d2"])

print("| model | deformation | components | ACD nodes / after contraction | ACD D | ACD D2 "
      "| CGAL nodes / after contraction | CGAL nodes over 3 runs | CGAL D | CGAL D2 |")
print("|---|---|---:|---:|---:|---:|---:|---:|---:|---:|")
for m in models:
    rep = json.load(open("%s/%s/report.json" % (out, m)))
    for e in rep["models"]:
        spec = "original" if e["name"] == "original" else "`%s`" % e["source"]
        acd, mcf = e["acd"], e.get("mcf", {})
        runs = mcf.get("run_node_counts", [])
        print("| %s | %s | %d | %s | %s | %s | %s | %s | %s | %s |" % (
            m, spec, e["components"], counts(acd), dist(acd.get("D")), dist(acd.get("D2")),
            counts(mcf) if "nodes" in mcf else "-",
            "%d–%d" % (min(runs), max(runs)) if runs else "-",
            dist(mcf.get("D")), dist(mcf.get("D2"))))
        if "run2_vs_run1_D" in mcf:  # the CGAL skeleton against itself: its noise floor
            print("| %s | CGAL run 2 vs run 1, same mesh | | | | | | | %s | %s |" % (
                m, dist(mcf["run2_vs_run1_D"]), dist(mcf["run2_vs_run1_D2"])))
PYEOF
cat "$OUT/table.md"

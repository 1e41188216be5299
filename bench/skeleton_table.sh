#!/usr/bin/env bash
# Skeletons under deformation (paper, Section 7, Figure 21): five models (three of the corpus the
# skeleton was first built on, then dino and man, not looked at while choosing its constants),
# each with two ARAP bends of different limbs, a twist of a limb about its own axis, a pose of a
# whole limb chain (a wide bend at the root, then a bend of the end), a rigid motion with
# non-uniform scaling, and a rigid motion alone (a control: the ACD skeleton should not change at
# all); the ACD skeleton of parts, the skeleton of the components themselves, and CGAL's
# mean-curvature-flow skeleton (three runs per mesh, since it differs run to run: its D2 is given for
# run 1 against run 1 and over all nine pairs of runs, with verdicts against both).
# The deformations were fixed before any result was looked at; a limb is named by the direction
# of its tip (see the figures in docs/SKELETON.md).
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
# limbs: model, first limb's tip direction, its bend axis and angle, second limb's, then the
# non-uniform scaling
poses() {
    local dir1=$1 axis1=$2 deg1=$3 dir2=$4 axis2=$5 deg2=$6 affine=$7
    echo --deform "bend:$dir1:$axis1:$deg1" --deform "bend:$dir2:$axis2:$deg2" --deform "twist:$dir1:60" \
        --deform "bend:$dir1:$axis1:$((deg1 / 2)):0.2:0.45;bend:$dir1:$axis1:$deg1" --deform "$affine" --deform $RIGID
}
run elephant $(poses +x z -40 -x z 30 affine:20,35,-10:1.3,1,0.8:0.2,0,0)
run camel $(poses +y x 35 -y x 30 affine:-15,0,30:1,1.25,0.85:0,0.1,0)
run armadillo $(poses +x z 40 -x z -40 affine:0,60,10:0.8,1.2,1:5,0,0)
run dino $(poses -x z 30 +x z -30 affine:20,35,-10:1.3,1,0.8:0.2,0,0)
run man $(poses -x y 30 +x y -30 affine:-15,0,30:1,1.25,0.85:0,0.1,0)

/usr/bin/python3 - "$OUT" elephant camel armadillo dino man >"$OUT/table.md" <<'PYEOF'
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

def corr(a):
    return "%d / %d" % (a["correspondence_D"], a["correspondence_D2"]) if "correspondence_D" in a else "-"

def upper(d):
    return d["distance"] if d else None

print("| model | deformation | components / parts | ACD nodes / after contraction | ACD D | ACD D2 "
      "| ACD D / D2, parts matched by vertices | components' D2 "
      "| CGAL nodes / after contraction | CGAL nodes over 3 runs | CGAL D | CGAL D2 | CGAL D2 over 3 x 3 runs: min–max (median) "
      "| ACD D2 <= CGAL D2 | ACD D2 <= CGAL's median |")
print("|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|:---:|:---:|")

def verdict_of(acd_d2, mcf_low, mcf_up):
    # Bracketed values compare by their proven ends: ACD's upper bound against CGAL's lower.
    return "yes" if acd_d2["distance"] <= mcf_low else ("open" if acd_d2["lower_bound"] <= mcf_up else "no")

def spread(pairs):
    # Every pair proven: min–max (median); otherwise the brackets' ends.
    lows, ups = sorted(p["lower_bound"] for p in pairs), sorted(p["distance"] for p in pairs)
    mid = len(pairs) // 2
    if lows == ups:
        return "%d–%d (%d)" % (ups[0], ups[-1], ups[mid]), lows[mid], ups[mid]
    return "%d–%d (%d–%d)" % (lows[0], ups[-1], lows[mid], ups[mid]), lows[mid], ups[mid]
for m in models:
    rep = json.load(open("%s/%s/report.json" % (out, m)))
    for e in rep["models"]:
        spec = "original" if e["name"] == "original" else "`%s`" % e["source"].replace("|", "\\|")
        acd, mcf = e["acd"], e.get("mcf", {})
        runs = mcf.get("run_node_counts", [])
        verdict, pair_cell, median_verdict = "-", "-", "-"
        if "D2" in acd and "D2" in mcf:
            verdict = verdict_of(acd["D2"], mcf["D2"]["lower_bound"], mcf["D2"]["distance"])
        if "D2" in acd and mcf.get("run_pairs_D2"):
            pair_cell, low, up = spread(mcf["run_pairs_D2"])
            median_verdict = verdict_of(acd["D2"], low, up)
        print("| %s | %s | %d / %d | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s |" % (
            m, spec, e["components"], e["parts"], counts(acd), dist(acd.get("D")), dist(acd.get("D2")),
            corr(acd), dist(e["acd_components"].get("D2")),
            counts(mcf) if "nodes" in mcf else "-",
            "%d–%d" % (min(runs), max(runs)) if runs else "-",
            dist(mcf.get("D")), dist(mcf.get("D2")), pair_cell, verdict, median_verdict))
        if "run2_vs_run1_D" in mcf:  # the CGAL skeleton against itself: its noise floor
            print("| %s | CGAL run 2 vs run 1, same mesh | | | | | | | | | %s | %s | | | |" % (
                m, dist(mcf["run2_vs_run1_D"]), dist(mcf["run2_vs_run1_D2"])))
PYEOF
cat "$OUT/table.md"

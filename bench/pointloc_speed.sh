#!/usr/bin/env bash
# Speed of point location (paper, Figure 20): the ACD hulls against the exact tests of the
# original model and the exact convex decomposition, measured in the same runs; medians of
# several runs as a Markdown table on stdout.
#
#   bench/pointloc_speed.sh [--model armadillo] [--tau 0.02] [--samples 1e8] [--repeat 5]
#                           [--runs 1] [--compare-samples 1e6] [--ecd-time-limit 60]
#                           [--threads 0] [--pointloc PATH] [--keep DIR]
#
# Each run is `pointloc data/meshes/MODEL.off --tau TAU --samples N --compare --repeat R
# --compare-samples K --ecd-time-limit S --json FILE`: one decomposition, then every timed
# pass R times; the hulls locate all N points, the exact methods (CGAL Side_of_triangle_mesh
# on 1 and all threads, acd::InsideTest, the ECD when libacd has one) the first K of the same
# points. Rates are medians over all passes of all runs (--runs separate processes); the
# ratios are of those medians.
set -euo pipefail

ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$ROOT"

MODEL="armadillo"; TAU="0.02"; SAMPLES="1e8"; REPEAT=5; RUNS=1; K="1e6"; ECD_LIMIT=60; THREADS=0
POINTLOC="build/bin/pointloc"; KEEP=""

usage() { sed -n '2,16p' "$0" | sed 's/^# \{0,1\}//'; }
while [[ $# -gt 0 ]]; do
    case "$1" in
        --model) MODEL="$2"; shift 2 ;;
        --tau) TAU="$2"; shift 2 ;;
        --samples) SAMPLES="$2"; shift 2 ;;
        --repeat) REPEAT="$2"; shift 2 ;;
        --runs) RUNS="$2"; shift 2 ;;
        --compare-samples) K="$2"; shift 2 ;;
        --ecd-time-limit) ECD_LIMIT="$2"; shift 2 ;;
        --threads) THREADS="$2"; shift 2 ;;
        --pointloc) POINTLOC="$2"; shift 2 ;;
        --keep) KEEP="$2"; shift 2 ;;
        -h|--help) usage; exit 0 ;;
        *) echo "pointloc_speed: unknown option $1" >&2; usage >&2; exit 2 ;;
    esac
done
[[ "$REPEAT" =~ ^[1-9][0-9]*$ ]] || { echo "pointloc_speed: --repeat needs a positive integer" >&2; exit 2; }
[[ "$RUNS" =~ ^[1-9][0-9]*$ ]] || { echo "pointloc_speed: --runs needs a positive integer" >&2; exit 2; }
[[ -x "$POINTLOC" ]] || { echo "pointloc_speed: $POINTLOC not found; run scripts/setup.sh first" >&2; exit 1; }

DIR="${KEEP:-$(mktemp -d)}"
mkdir -p "$DIR"
[[ -z "$KEEP" ]] && trap 'rm -rf "$DIR"' EXIT

for ((r = 1; r <= RUNS; r++)); do
    [[ -t 2 ]] && echo "pointloc_speed: run $r of $RUNS" >&2
    "$POINTLOC" "data/meshes/$MODEL.off" --tau "$TAU" --samples "$SAMPLES" --threads "$THREADS" --compare \
        --repeat "$REPEAT" --compare-samples "$K" --ecd-time-limit "$ECD_LIMIT" --json "$DIR/run$r.json" \
        > "$DIR/run$r.txt"
done

/usr/bin/python3 - "$DIR" "$RUNS" <<'PY'
import json, os, statistics, sys
runs = [json.load(open(f"{sys.argv[1]}/run{r}.json")) for r in range(1, int(sys.argv[2]) + 1)]
med = statistics.median
j0 = runs[0]
passes = len(runs) * j0["repeat"]
load = os.getloadavg()
print(f"Model {j0['model']}, τ = {j0['tau']}, {j0['samples']:,} points, {j0['threads']} threads; "
      f"{len(runs)} run(s) x {j0['repeat']} passes (medians, min–max in brackets); exact methods timed on "
      f"the first {j0['compare']['samples']:,} points of the same stream. Load average at the end: "
      f"{load[0]:.1f}, {load[1]:.1f}, {load[2]:.1f}.\n")
print("| method | threads | preparation s | points timed | points/s (wall) | points per CPU second | time for all points s | total s (Figure 20) | answers differing from acd::InsideTest |")
print("|---|---:|---:|---:|---:|---:|---:|---:|---:|")
def key(m): return (m["method"], m.get("threads"))
keys = [key(m) for m in j0["compare"]["methods"]]
rate_of = {}
cpu_rate_of = {}
for k in keys:
    ms = [m for j in runs for m in j["compare"]["methods"] if key(m) == k and m["available"]]
    if not ms:
        note = next(m for m in j0["compare"]["methods"] if key(m) == k).get("note", "not available")
        print(f"| {k[0]} | | {note} | | | | | | |")
        continue
    pts = ms[0]["points"]
    secs = [s for m in ms for s in m["seconds_runs"]]
    rates = [pts / s for s in secs]
    rate_of[k] = med(rates)
    cpus = [c for m in ms for c in m["cpu_seconds_runs"]]
    per_cpu = pts / med(cpus) if med(cpus) > 0 else 0.0
    cpu_rate_of[k] = per_cpu
    forN = med(secs) * j0["samples"] / pts
    prep = med([m["prepare_seconds"] for m in ms])
    star = "*" if ms[0]["extrapolated"] else ""
    diff = ms[0]["disagreements_with_exact"]
    print(f"| {k[0]} | {ms[0]['threads']} | {prep:.2f} | {pts:,} | {med(rates) / 1e6:.3g} M [{min(rates) / 1e6:.3g}–{max(rates) / 1e6:.3g}] "
          f"| {per_cpu / 1e6:.3g} M "
          f"| {forN:.2f}{star} | {prep + forN:.1f}{star} | {'-' if diff is None else diff} |")
loc = [s for j in runs for s in j["location_seconds_runs"]]
cpu = [s for j in runs for s in j["location_cpu_seconds_runs"]]
print()
print(f"- location of {j0['samples']:,} points with the hulls: median {med(loc):.3f} s wall "
      f"(min {min(loc):.3f}, max {max(loc):.3f}), {med(cpu):.3f} s CPU; decomposition "
      f"{med([j['decomposition_seconds'] for j in runs]):.1f} s; grid {med([j['index']['seconds'] for j in runs]):.3f} s")
hull = rate_of.get(("ACD hulls (grid)", j0["threads"]))
c1 = rate_of.get(("model: CGAL Side_of_triangle_mesh", 1))
cn = rate_of.get(("model: CGAL Side_of_triangle_mesh", j0["threads"]))
if hull and c1:
    print(f"- hull rate / CGAL Side_of_triangle_mesh rate on 1 thread, wall clock, as measured: {hull / c1:.1f}x; "
          f"against CGAL on {j0['threads']} threads: {hull / cn:.1f}x")
    hc = cpu_rate_of[("ACD hulls (grid)", j0["threads"])]
    cc = cpu_rate_of[("model: CGAL Side_of_triangle_mesh", 1)]
    n = j0["threads"]
    print(f"- per CPU second (independent of the share of the machine the run got): hulls {hc / 1e6:.3g} M, "
          f"CGAL {cc / 1e6:.3g} M points, {hc / cc:.1f}x; on {n} otherwise idle cores the hulls would locate "
          f"{j0['samples']:,} points in about {j0['samples'] / hc / n:.2f} s wall, {n * hc / cc:.0f}x CGAL on one thread")
e = j0["exact"]
print(f"- error (first {e['samples']:,} points, acd::InsideTest): false inside {e['false_inside']}, "
      f"false outside {e['false_outside']}, error rate {100 * e['error_rate']:.3f} % "
      f"[{100 * e['error_rate_ci95'][0]:.3f}, {100 * e['error_rate_ci95'][1]:.3f}]")
ecd = j0["compare"]["ecd"]
if ecd["available"]:
    print(f"- exact convex decomposition: {'finished' if ecd['finished'] else 'unfinished'}, "
          f"{ecd['pieces']} pieces, {ecd['seconds']:.1f} s (limit {ecd['time_limit_seconds']:g} s)"
          + (f": {ecd['note']}" if ecd["note"] else ""))
else:
    print(f"- exact convex decomposition: {ecd['note']}")
print("- *: extrapolated linearly from the points timed")
PY

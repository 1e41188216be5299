#!/usr/bin/env bash
# Speed of point location (paper, Figure 20): the ACD hulls against the exact tests of the
# original model and the exact convex decomposition, measured in the same runs; medians of
# several runs as a Markdown table on stdout.
#
#   bench/pointloc_speed.sh [--model armadillo] [--tau 0.02] [--samples 1e8] [--repeat 5]
#                           [--compare-samples 1e6] [--ecd-time-limit 60] [--threads 0]
#                           [--pointloc PATH] [--keep DIR]
#
# Each run is `pointloc data/meshes/MODEL.off --tau TAU --samples N --compare
# --compare-samples K --ecd-time-limit S --json FILE`: the hulls locate all N points; the
# exact methods (CGAL Side_of_triangle_mesh on 1 and all threads, acd::InsideTest, the ECD
# when libacd has one) are timed on the first K of the same points. Rates are medians over
# the runs; ratios are computed per run, then their median is taken.
set -euo pipefail

ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$ROOT"

MODEL="armadillo"; TAU="0.02"; SAMPLES="1e8"; REPEAT=5; K="1e6"; ECD_LIMIT=60; THREADS=0
POINTLOC="build/bin/pointloc"; KEEP=""

usage() { sed -n '2,16p' "$0" | sed 's/^# \{0,1\}//'; }
while [[ $# -gt 0 ]]; do
    case "$1" in
        --model) MODEL="$2"; shift 2 ;;
        --tau) TAU="$2"; shift 2 ;;
        --samples) SAMPLES="$2"; shift 2 ;;
        --repeat) REPEAT="$2"; shift 2 ;;
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
[[ -x "$POINTLOC" ]] || { echo "pointloc_speed: $POINTLOC not found; run scripts/setup.sh first" >&2; exit 1; }

DIR="${KEEP:-$(mktemp -d)}"
mkdir -p "$DIR"
[[ -z "$KEEP" ]] && trap 'rm -rf "$DIR"' EXIT

for ((r = 1; r <= REPEAT; r++)); do
    [[ -t 2 ]] && echo "pointloc_speed: run $r of $REPEAT" >&2
    "$POINTLOC" "data/meshes/$MODEL.off" --tau "$TAU" --samples "$SAMPLES" --threads "$THREADS" --compare \
        --compare-samples "$K" --ecd-time-limit "$ECD_LIMIT" --json "$DIR/run$r.json" > "$DIR/run$r.txt"
done

/usr/bin/python3 - "$DIR" "$REPEAT" <<'PY'
import json, statistics, sys
runs = [json.load(open(f"{sys.argv[1]}/run{r}.json")) for r in range(1, int(sys.argv[2]) + 1)]
med = statistics.median
j0 = runs[0]
def rows(j):
    return {(m["method"], m.get("threads")): m for m in j["compare"]["methods"]}
print(f"Model {j0['model']}, τ = {j0['tau']}, {j0['samples']:,} points, {j0['threads']} threads, "
      f"{len(runs)} runs (medians; min–max in brackets). Exact methods timed on the first "
      f"{j0['compare']['samples']:,} points of the same stream.\n")
print("| method | threads | preparation s | points timed | points/s | time for all points s | total s (Figure 20) | answers differing from acd::InsideTest |")
print("|---|---:|---:|---:|---:|---:|---:|---:|")
keys = [(m["method"], m.get("threads")) for m in j0["compare"]["methods"]]
for key in keys:
    ms = [rows(j).get(key) for j in runs]
    ms = [m for m in ms if m and m["available"]]
    if not ms:
        note = rows(j0)[key].get("note", "not available")
        print(f"| {key[0]} | | {note} | | | | | |")
        continue
    rate = [m["points_per_second"] for m in ms]
    def f(x): return f"{med(x):.3g} [{min(x):.3g}–{max(x):.3g}]"
    star = "*" if ms[0]["extrapolated"] else ""
    diff = ms[0]["disagreements_with_exact"]
    print(f"| {key[0]} | {ms[0]['threads']} | {med([m['prepare_seconds'] for m in ms]):.2f} | {ms[0]['points']:,} "
          f"| {f(rate)} | {med([m['seconds_for_all_points'] for m in ms]):.2f}{star} "
          f"| {med([m['total_seconds'] for m in ms]):.1f}{star} | {'-' if diff is None else diff} |")
loc = [j["location_seconds"] for j in runs]
s1 = [j["compare"]["speedup_vs_cgal_1_thread"] for j in runs]
s2 = [j["compare"]["speedup_vs_cgal_same_threads"] for j in runs]
print()
print(f"- location of {j0['samples']:,} points with the hulls: median {med(loc):.3f} s "
      f"(min {min(loc):.3f}, max {max(loc):.3f}); decomposition median "
      f"{med([j['decomposition_seconds'] for j in runs]):.1f} s; index {med([j['index']['seconds'] for j in runs]):.3f} s")
print(f"- hull rate / CGAL Side_of_triangle_mesh rate on 1 thread: median {med(s1):.1f}x "
      f"(min {min(s1):.1f}, max {max(s1):.1f}); against CGAL on {j0['threads']} threads: median {med(s2):.1f}x")
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

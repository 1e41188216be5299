#!/usr/bin/env bash
# The twisty-passage comparison (docs/PLANNER.md, "Soup scenes"; docs/BENCHMARKS.md): generates
# the soup scenes, searches the milestones the acd and bridge-test samplers need for 90 %
# success (--n90), runs uniform, Gaussian and obstacle-based sampling at the bridge test's N
# (below 90 % there, their own N90 is larger still), races OMPL's planners against the clock
# (--race, in parallel with the searches: it is bounded by the clock, not by the processor),
# and plots success against N.
#   bench/planner_soup.sh [SCENARIO] [BUILD_DIR]
# Settings by environment: N90_START (25), N90_MAX (8000), N90_TRIALS (20), TIME_LIMIT (30),
# RUNS (10). Writes out/planner/<name>/{n90/,others/,race/,points.csv,success.png}.
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$ROOT"
SCENARIO="${1:-scenarios/twisty.yaml}"
BUILD="${2:-build}"
NAME="$(basename "$SCENARIO" .yaml)"
OUT="out/planner/$NAME"
TRIALS="${N90_TRIALS:-20}"
mkdir -p "$OUT"
"$BUILD/bin/planner_scenes" scenarios/generated
# 1. Milestones to 90 % for acd and bridge_test, and OMPL's planners against the clock.
"$BUILD/bin/planner" "$SCENARIO" --no-fixed -s acd,bridge_test --n90 --n90-start "${N90_START:-25}" \
    --n90-max "${N90_MAX:-8000}" --n90-trials "$TRIALS" -o "$OUT/n90" > "$OUT/n90.txt" &
search=$!
"$BUILD/bin/planner" "$SCENARIO" --no-fixed --race --time-limit "${TIME_LIMIT:-30}" --runs "${RUNS:-10}" \
    -o "$OUT/race" > "$OUT/race.txt"
wait "$search"
cat "$OUT/n90.txt" "$OUT/race.txt"
# 2. The other samplers at the bridge test's N.
N="$(awk -F, '$1 == "bridge_test" {print $2}' "$OUT/n90/n90.csv")"
N="${N:-${N90_MAX:-8000}}"
"$BUILD/bin/planner" "$SCENARIO" -n "$N" -t "$TRIALS" -s uniform,gaussian,obstacle_based -o "$OUT/others" | tee "$OUT/others.txt"
# Every point measured, in sweep.csv's format, and the plot.
/usr/bin/python3 - "$OUT" <<'PY'
import json, sys
out = sys.argv[1]
rows = open(out + "/n90/n90_points.csv").read().splitlines()
for s in json.load(open(out + "/others/results.json"))["samplers"]:
    rows.append("%s,%d,%d,%d,%g,%g,%g,%g" % (s["sampler"], s["samples"], s["trials"], s["successes"],
                                             s["success_rate"], s["ci95"][0], s["ci95"][1], s["mean_seconds"]))
open(out + "/points.csv", "w").write("\n".join(rows) + "\n")
PY
/usr/bin/python3 apps/planner/plot_success.py "$OUT/points.csv" "$OUT/success.png" "$NAME.yaml"
echo "plot: $OUT/success.png"

#!/usr/bin/env bash
# The twisty-passage comparison (docs/PLANNER.md, "Soup scenes"; docs/BENCHMARKS.md): generates
# the soup scenes, searches the milestones the acd sampler needs for 90 % success (--n90), runs
# the other samplers at that N, races OMPL's planners against the clock (--race), and plots
# success against N.
#   bench/planner_soup.sh [SCENARIO] [BUILD_DIR]
# Settings by environment: N90_START (250), N90_MAX (8000), N90_TRIALS (20), OTHERS_TRIALS (10),
# TIME_LIMIT (30), RUNS (10). Writes out/planner/<name>/{n90/,others/,race/,success.png}.
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$ROOT"
SCENARIO="${1:-scenarios/twisty.yaml}"
BUILD="${2:-build}"
NAME="$(basename "$SCENARIO" .yaml)"
OUT="out/planner/$NAME"
mkdir -p "$OUT"
"$BUILD/bin/planner_scenes" scenarios/generated
# 1. Milestones to 90 % for the acd sampler.
"$BUILD/bin/planner" "$SCENARIO" --no-fixed -s acd --n90 --n90-start "${N90_START:-250}" \
    --n90-max "${N90_MAX:-8000}" --n90-trials "${N90_TRIALS:-20}" -o "$OUT/n90" | tee "$OUT/n90.txt"
N90="$(awk -F, '$1 == "acd" {print $2}' "$OUT/n90/n90.csv")"
if [[ -z "$N90" ]]; then echo "acd did not reach 90 % by N90_MAX"; exit 0; fi
# 2. The other samplers at that N (a full search for them costs hours: see BENCHMARKS.md).
"$BUILD/bin/planner" "$SCENARIO" -n "$N90" -t "${OTHERS_TRIALS:-10}" \
    -s uniform,gaussian,obstacle_based,bridge_test -o "$OUT/others" | tee "$OUT/others.txt"
# 3. OMPL's planners against the clock.
"$BUILD/bin/planner" "$SCENARIO" --no-fixed --race --time-limit "${TIME_LIMIT:-30}" --runs "${RUNS:-10}" \
    -o "$OUT/race" | tee "$OUT/race.txt"
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

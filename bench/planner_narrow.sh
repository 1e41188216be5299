#!/usr/bin/env bash
# The planner's experiment on one scenario (default scenarios/narrow.yaml): the table at the
# scenario's sample count and trials, the sweep over sample counts, and the plot.
#   bench/planner_narrow.sh [SCENARIO] [BUILD_DIR]
# Writes out/planner/<name>/{table.txt,results.json,benchmark.log,best_path.txt,sweep.csv,success.png}
# and, for a box robot of size ROBOT_BOX="SX SY SZ" (set for narrow.yaml), path.png.
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$ROOT"
SCENARIO="${1:-scenarios/narrow.yaml}"
BUILD="${2:-build}"
NAME="$(basename "$SCENARIO" .yaml)"
OUT="out/planner/$NAME"
mkdir -p "$OUT"
"$BUILD/bin/planner" "$SCENARIO" --sweep -o "$OUT" | tee "$OUT/table.txt"
/usr/bin/python3 apps/planner/plot_success.py "$OUT/sweep.csv" "$OUT/success.png" "$NAME.yaml"
echo "plot: $OUT/success.png"
ROBOT_BOX="${ROBOT_BOX:-}"
if [[ -z "$ROBOT_BOX" && "$NAME" == narrow ]]; then ROBOT_BOX="1.2 0.8 0.3"; fi
if [[ -n "$ROBOT_BOX" && -f "$OUT/best_path.txt" ]]; then
    # shellcheck disable=SC2086
    /usr/bin/python3 apps/planner/plot_path.py "$OUT/free_space_acd.obj" "$OUT/best_path.txt" "$OUT/path.png" $ROBOT_BOX \
        "$NAME.yaml: free-space ACD and the shortest path"
    echo "path picture: $OUT/path.png"
fi

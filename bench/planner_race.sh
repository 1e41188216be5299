#!/bin/sh
# The race on OMPL.app problem files (docs/PLANNER.md, "The race"): the generated problems in
# OMPL.app's format (planner_scenes), every planner of the race on each, OMPL's benchmark log,
# race.csv and a plot per problem, and the Markdown table of docs/PLANNER.md on stdout.
#   [PLANNERS=PRM_acd,RRTConnect,...] bench/planner_race.sh [TIME_LIMIT] [RUNS] [PROBLEM ...]
# Defaults: 10 s, 5 runs, the narrow passages (twisty_cfg alpha_links bug_trap), every planner.
set -eu
cd "$(dirname "$0")/.."
limit=${1:-10}
runs=${2:-5}
shift 2 2>/dev/null || shift $#
problems=${*:-twisty_cfg alpha_links bug_trap}
out=out/planner_race
build/bin/planner_scenes scenarios/generated
for p in $problems; do
  echo "== $p" >&2
  build/bin/planner "scenarios/generated/ompl_app/$p.cfg" --race --no-fixed --time-limit "$limit" --runs "$runs" \
    ${PLANNERS:+--planners "$PLANNERS"} -o "$out/$p" -q > "$out.$p.txt" 2>&1 || { cat "$out.$p.txt" >&2; exit 1; }
  /usr/bin/python3 apps/planner/plot_race.py "$out/$p/race_runs.csv" "$out/$p/race.png" "$p: $runs runs, $limit s each"
done
/usr/bin/python3 bench/planner_race_table.py "$out" $problems

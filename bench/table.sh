#!/bin/sh
# The paper's Table 1 (solid and surface ACD against exact decomposition) and the data of its
# Figures 18-19 (components and time against tau, with and without feature grouping), then the
# plots. Long: the solid ECD of each model may run up to EXACT_LIMIT seconds.
#
#   bench/table.sh                      # after scripts/setup.sh; writes out/table/ and docs/images/plot-*.png
#   EXACT_LIMIT=600 bench/table.sh      # a longer cap for the exact decomposition
set -eu
cd "$(dirname "$0")/.."
TABLE=${TABLE:-build/bin/acd-table}
OUT=${OUT:-out/table}
EXACT_LIMIT=${EXACT_LIMIT:-120}
MODELS=${MODELS:-elephant,knot,eight,handle,dino,armadillo,mushroom,ChineseDragon-10kv,pipe,blob-closed,u,joint,dragknob,part,anchor}
SWEEP_MODELS=${SWEEP_MODELS:-armadillo,elephant}
SWEEP_TAUS=${SWEEP_TAUS:-0.4,0.2,0.1,0.05,0.02,0.01}
mkdir -p "$OUT"
"$TABLE" --models "$MODELS" --taus 0.2,0.02 --exact-time-limit "$EXACT_LIMIT" \
  --sweep-models "$SWEEP_MODELS" --sweep-taus "$SWEEP_TAUS" \
  --markdown "$OUT/table.md" --json "$OUT/table.json"
/usr/bin/python3 scripts/plot_table.py "$OUT/table.json" --out docs/images

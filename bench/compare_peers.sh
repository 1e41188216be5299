#!/usr/bin/env bash
# acd against CoACD 1.0.13 and V-HACD 4.1, built from source and run side by side on the same
# inputs; prints the tables of docs/BENCHMARKS.md ("Against CoACD and V-HACD").
#
#   bench/compare_peers.sh [--set corpus|heldout|all] [--models a,b] [--only acd|peers|all] [--out DIR]
#
#   --set     corpus: the ten closed corpus models; heldout: the 15 held-out models
#             ($ACD_WIDE_DATA/compare, never used for tuning); all (default): both
#   --only    run only acd or only the peers (the tables use whatever is there)
#   --out     where each run's hulls, log and scores are published (default out/compare_peers)
#   --existing  table only the runs already cached, start none
#
# Environment: ACD_BENCH_CACHE (default ~/.cache/acd-bench): the peers' build and every run and
# score, keyed by the SHA-256 of input, binary and flags, so a re-run after an acd change runs
# only acd and a cold run can be stopped and resumed. ACD_PEERS_SRC: the folder holding the
# peers' source archives and their build.sh (built once, into the cache, when missing).
# ACD_WIDE_DATA: the wide data set (its compare/ folder is the held-out set).
#
# acd: `acd decompose MODEL -t TAU --threads 2` at the fixed tau list of bench/compare_peers.py;
# CoACD: `coacd -i model.obj -o hulls.obj -t T -s SEED`, T in 0.1 0.05 0.02, seeds 0 1 2;
# V-HACD: `vhacd model.obj` and `vhacd model.obj -h 128`. The peers read the model as an OBJ
# written by `acd convert` (as read, no repair). Scores: `acd evaluate --samples 1000000` and
# `acd-score --samples 1000000`. One run at a time.
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$ROOT"
if [[ "${1:-}" == -h || "${1:-}" == --help ]]; then sed -n '2,25p' "$0" | sed 's/^# \{0,1\}//'; exit 0; fi
cmake --build build --target acd_cli acd_score >/dev/null
/usr/bin/python3 bench/compare_peers.py run "$@"
/usr/bin/python3 bench/compare_peers.py table "$@"

#!/usr/bin/env bash
# The project's main job: set up, then decompose a real corpus model
# (the elephant) at concavity tolerance 0.05 and print the summary table. Only the library and
# the acd command are built here; scripts/run_tests.sh builds the rest.
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$ROOT"

scripts/setup.sh acd_cli
echo "[run_main] build/bin/acd decompose data/meshes/elephant.off -t 0.05 -o out/elephant"
mkdir -p out
exec build/bin/acd decompose data/meshes/elephant.off -t 0.05 -o out/elephant

#!/usr/bin/env bash
# Makes docs/BENCHMARKS.md in one run on one commit: the peers (bench/compare_peers.sh, corpus and
# held-out models), assemblies (bench/compare_assemblies.py), speed over the corpus (bench/run_corpus.sh), tau kept (bench/tau_kept.sh) and
# invariance under rigid motion (bench/invariance.sh), each table placed into
# bench/BENCHMARKS.template.md with the command that made it. Dense inputs against V-HACD: bench/dense_speed.py.
#
#   bench/all.sh [--out DIR] [--doc PATH] [--existing] [--assemble-only]
#
#   --out   where this run's outputs go (default out/all; emptied first, except the peers' cache)
#   --doc   the document written (default docs/BENCHMARKS.md)
#   --existing  table only the peer runs already in the cache and start none (acd itself always
#           runs: its runs are cached by binary, so they are this commit's; CoACD on a cold
#           cache takes hours: run `bench/compare_peers.sh --only peers` first, in parts, or in
#           shards with bench/compare_peers.py's --shard); the tables say how many runs each has
#   --assemble-only  no runs: write the document again from OUT/tables (after a template edit)
#
# About 2.5 h of CoACD on a cold cache (2 cores), and several hours more for the assemblies (CoACD
# takes 2-25 min per assembly); with the peers cached, about 1 h. The peers'
# runs and every acd run of the comparison are cached by hash (bench/compare_peers.py), so they
# are reused exactly when input, binary and flags are the same.
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$ROOT"
OUT="out/all"
DOC="docs/BENCHMARKS.md"
EXISTING=()
ASSEMBLE_ONLY=0
while [[ $# -gt 0 ]]; do
    case "$1" in
        --out) OUT="$2"; shift 2 ;;
        --doc) DOC="$2"; shift 2 ;;
        --existing) EXISTING=(--existing); shift ;;
        --assemble-only) ASSEMBLE_ONLY=1; shift ;;
        -h|--help) sed -n '2,20p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
        *) echo "all: unknown option $1" >&2; exit 2 ;;
    esac
done
say() { echo "[all $(date +%T)] $*" >&2; }
if (( ! ASSEMBLE_ONLY )); then
rm -rf "$OUT"; mkdir -p "$OUT/tables"
start=$(date +%s)

cmake --build build --target acd_cli acd_score -j"$(nproc)" >/dev/null
commit="$(git rev-parse --short HEAD)"
git diff --quiet HEAD -- libacd apps bench || commit="$commit+dirty"
{
    echo "commit=$commit"
    echo "date=$(date -u '+%Y-%m-%d %H:%M UTC')"
    echo "acd_sha256=$(sha256sum build/bin/acd | cut -c1-16)"
    echo "machine=$(nproc) cores ($(sed -n 's/^model name[[:space:]]*: //p' /proc/cpuinfo | head -n 1)), $(free -g | awk '/Mem:/ {print $2}') GiB, $(. /etc/os-release; echo "$PRETTY_NAME"), $(g++ --version | head -n 1)"
    if (( ${#EXISTING[@]} )); then
        echo "peers_mode=This run tabled only the peer runs already in the cache (\`--existing\`): the \`runs\` column says how many of CoACD's three seeds each setting had; the median and spread are over those."
    else
        echo "peers_mode=Every peer run of the list above is in this run (from the cache where input, binary and flags were the same)."
    fi
} >"$OUT/tables/header.env"

say "peers: corpus"
bench/compare_peers.sh --set corpus --out "$OUT/peers" "${EXISTING[@]}" >"$OUT/tables/peers_corpus.md"
say "peers: held-out"
bench/compare_peers.sh --set heldout --out "$OUT/peers" "${EXISTING[@]}" >"$OUT/tables/peers_heldout.md"
say "assemblies"
/usr/bin/python3 bench/compare_assemblies.py run --out "$OUT/assemblies" "${EXISTING[@]}" >&2
/usr/bin/python3 bench/compare_assemblies.py table --out "$OUT/assemblies" >"$OUT/tables/assemblies.md"
say "speed"
bench/run_corpus.sh --taus "0.2 0.05 0.02" --repeat 3 --out "$OUT/speed" >"$OUT/tables/speed.md" || true
say "dense inputs"
/usr/bin/python3 bench/dense_speed.py --tau 0.05 --repeat 3 --out "$OUT/dense" >"$OUT/tables/dense.md" || true
/usr/bin/python3 bench/dense_speed.py --tau 0.05 --repeat 3 --acd-flags="--working-share 0" --out "$OUT/dense_full" \
    >"$OUT/tables/dense_full.md" || true
say "tau kept"
bench/tau_kept.sh --out "$OUT/tau_kept" >"$OUT/tables/tau_kept.md" || true
say "invariance"
bench/invariance.sh --jobs 1 --threads 2 --out "$OUT/invariance" >"$OUT/tables/invariance.md" || true
echo "minutes=$(( ($(date +%s) - start) / 60 ))" >>"$OUT/tables/header.env"
fi

/usr/bin/python3 - "$OUT/tables" bench/BENCHMARKS.template.md "$DOC" <<'PY'
import os, re, sys
tables, template, doc = sys.argv[1:]
values = dict(l.rstrip("\n").split("=", 1) for l in open(os.path.join(tables, "header.env")))
def fill(m):
    key = m.group(1)
    if key in values:
        return values[key]
    return open(os.path.join(tables, key + ".md")).read().strip()
open(doc, "w").write(re.sub(r"\{\{(\w+)\}\}", fill, open(template).read()))
PY
say "wrote $DOC"

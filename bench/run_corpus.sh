#!/usr/bin/env bash
# Benchmark the acd CLI over the mesh corpus and print a Markdown table.
#
#   bench/run_corpus.sh [--taus "0.2 0.05 0.02"] [--models "elephant camel"]
#                       [--no-grouping] [--repeat N] [--out DIR] [--acd PATH]
#
#   --taus         concavity tolerances τ (default: 0.2 0.05 0.02)
#   --models       corpus model names, files data/meshes/NAME.off (default: all 12)
#   --no-grouping  also run every case with the CLI's --no-grouping, so both
#                  variants (grouping on / off) appear in the table
#   --repeat N     run each case N times; wall time is the median, memory the max
#   --out DIR      where each run writes its output (default: out/bench)
#   --acd PATH     the CLI to run (default: build/bin/acd)
#
# Each run is `/usr/bin/time -v ACD decompose data/meshes/MODEL.off -t TAU
# -o OUTDIR --quiet`; the row is read from OUTDIR/report.json (components,
# totals.max_concavity, input.edges, input.notch_fraction, timing.total_seconds)
# and from /usr/bin/time (maximum resident set size). Progress goes to stderr,
# the table to stdout. Exits 1 if any run failed (its row says FAILED).
set -euo pipefail

ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$ROOT"

TAUS="0.2 0.05 0.02"
MODELS="elephant armadillo bunny00 camel cow dino homer handle knot eight mushroom ChineseDragon-10kv"
BOTH_GROUPING=0
REPEAT=1
OUTROOT="out/bench"
ACD="build/bin/acd"

usage() { sed -n '2,20p' "$0" | sed 's/^# \{0,1\}//'; }
while [[ $# -gt 0 ]]; do
    case "$1" in
        --taus) TAUS="$2"; shift 2 ;;
        --models) MODELS="$2"; shift 2 ;;
        --no-grouping) BOTH_GROUPING=1; shift ;;
        --repeat) REPEAT="$2"; shift 2 ;;
        --out) OUTROOT="$2"; shift 2 ;;
        --acd) ACD="$2"; shift 2 ;;
        -h|--help) usage; exit 0 ;;
        *) echo "run_corpus: unknown option $1" >&2; usage >&2; exit 2 ;;
    esac
done
[[ "$REPEAT" =~ ^[1-9][0-9]*$ ]] || { echo "run_corpus: --repeat needs a positive integer" >&2; exit 2; }
[[ -x /usr/bin/time ]] || { echo "run_corpus: /usr/bin/time missing (apt-get install time)" >&2; exit 1; }
command -v jq >/dev/null 2>&1 || { echo "run_corpus: jq missing (apt-get install jq)" >&2; exit 1; }
[[ -x "$ACD" ]] || { echo "run_corpus: $ACD not found; run scripts/setup.sh first" >&2; exit 1; }

VARIANTS=(on)
(( BOTH_GROUPING )) && VARIANTS=(on off)

median() { sort -g | awk '{a[NR]=$1} END {if (NR==0) exit; if (NR%2) print a[(NR+1)/2]; else print (a[NR/2]+a[NR/2+1])/2}'; }

ROWS=()
declare -A TOTAL_TIME TOTAL_RSS TOTAL_FAIL
failed=0

for model in $MODELS; do
    mesh="data/meshes/$model.off"
    if [[ ! -f "$mesh" ]]; then
        echo "run_corpus: $mesh not found (scripts/fetch_corpus.sh)" >&2
        failed=1
        continue
    fi
    for tau in $TAUS; do
        for grp in "${VARIANTS[@]}"; do
            key="$tau|$grp"
            outdir="$OUTROOT/$model-t$tau-g$grp"
            extra=()
            [[ "$grp" == off ]] && extra=(--no-grouping)
            times=()
            rss_kb=0
            ok=1
            for ((r = 1; r <= REPEAT; r++)); do
                echo "[bench] $model τ=$tau grouping=$grp run $r/$REPEAT" >&2
                rm -rf "$outdir"
                mkdir -p "$outdir"
                tfile="$outdir/time.txt"
                rc=0
                /usr/bin/time -v -o "$tfile" "$ACD" decompose "$mesh" -t "$tau" -o "$outdir" --quiet "${extra[@]}" \
                        >"$outdir/stdout.txt" 2>"$outdir/stderr.txt" || rc=$?
                # 4: finished, but some component is still above tau; 8: some hull beyond tau (both in the row).
                if (( rc == 2 )) && grep -q "open mesh" "$outdir/stderr.txt"; then
                    ok=2; break   # refused on purpose: the solid decomposition needs a closed mesh
                elif (( rc != 0 && rc != 4 && rc != 8 )); then
                    echo "[bench]   FAILED (see $outdir/stderr.txt)" >&2
                    ok=0; break
                fi
                if ! jq -e 'type == "object"' "$outdir/report.json" >/dev/null 2>&1; then
                    echo "[bench]   FAILED: missing or invalid $outdir/report.json" >&2
                    ok=0; break
                fi
                rss=$(sed -n 's/^[[:space:]]*Maximum resident set size (kbytes): *//p' "$tfile")
                (( ${rss:-0} > rss_kb )) && rss_kb=${rss:-0}
                t=$(jq -r '.timing.total_seconds // empty' "$outdir/report.json")
                if [[ -z "$t" ]]; then   # fall back to the process wall clock
                    t=$(sed -n 's/^[[:space:]]*Elapsed (wall clock) time.*: *//p' "$tfile" |
                        awk -F: '{s=0; for (i=1;i<=NF;i++) s=s*60+$i; print s}')
                fi
                times+=("$t")
            done
            if (( ok == 2 )); then
                ROWS+=("| $model | | | $tau | $grp | refused: open mesh | | | |")
                continue
            fi
            if (( ! ok )); then
                failed=1
                TOTAL_FAIL[$key]=1
                ROWS+=("| $model | | | $tau | $grp | FAILED | | | |")
                continue
            fi
            IFS=$'\t' read -r edges notch comps maxc < <(jq -r '[
                    (.input.edges // "?"),
                    (if .input.notch_fraction == null then "?" else (.input.notch_fraction * 100 * 10 | round / 10) end),
                    ((.components | length | tostring) + (if (.totals.unresolved // 0) > 0 then " (\(.totals.unresolved) unresolved)" else "" end)),
                    (.totals.max_concavity // "?")
                ] | map(tostring) | join("\t")' "$outdir/report.json")
            [[ "$maxc" != "?" ]] && maxc=$(printf '%.4g' "$maxc")
            tmed=$(printf '%s\n' "${times[@]}" | median)
            rss_mb=$(awk -v k="$rss_kb" 'BEGIN {printf "%.1f", k / 1024}')
            ROWS+=("| $model | $edges | $notch | $tau | $grp | $comps | $maxc | $(printf '%.3f' "$tmed") | $rss_mb |")
            TOTAL_TIME[$key]=$(awk -v a="${TOTAL_TIME[$key]:-0}" -v b="$tmed" 'BEGIN {print a + b}')
            prev=${TOTAL_RSS[$key]:-0}
            TOTAL_RSS[$key]=$(awk -v a="$prev" -v b="$rss_mb" 'BEGIN {print (b > a ? b : a)}')
        done
    done
done

echo "| model | edges | notch % | τ | grouping | components | max concavity | wall time (s) | peak RSS (MB) |"
echo "|---|---:|---:|---:|:---:|---:|---:|---:|---:|"
for row in "${ROWS[@]}"; do echo "$row"; done
for tau in $TAUS; do
    for grp in "${VARIANTS[@]}"; do
        key="$tau|$grp"
        [[ -n "${TOTAL_TIME[$key]:-}" || -n "${TOTAL_FAIL[$key]:-}" ]] || continue
        note=""
        [[ -n "${TOTAL_FAIL[$key]:-}" ]] && note=" (some runs failed)"
        printf '| **total**%s | | | %s | %s | | | %.3f | %s |\n' "$note" "$tau" "$grp" \
            "${TOTAL_TIME[$key]:-0}" "${TOTAL_RSS[$key]:-}"
    done
done
exit "$failed"

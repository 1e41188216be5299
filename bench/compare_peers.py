#!/usr/bin/python3
"""Table half of bench/compare_peers.sh: acd's parts at the fidelity of each peer setting.

  compare_peers.py extend RESULTS PEERS MODELS...  -> "MODEL TAU" lines still to run
  compare_peers.py table  RESULTS PEERS MODELS...  -> Markdown table on stdout, RESULTS/runs.tsv

RESULTS/MODEL/tTAU/ holds one decompose run: report.json, eval.json (acd evaluate --json),
rc (decompose's exit code) and commit (what was measured).

Interpolation (the rule docs/BENCHMARKS.md states): per model and figure (excess, lower is
better; IoU, higher is better) the runs are reduced to their envelope -- sorted by parts, a run
is kept only when its figure is strictly better than that of every run with fewer parts (ties
in parts keep the best). The target is bracketed by the envelope run with the fewest parts
that meets it and the envelope run just before it, which misses it; acd's parts there are
interpolated linearly in log(parts) against the figure. A non-monotone figure in tau thus
never lowers the count: a finer tau whose figure happens to be worse is simply not used.
"""
import json
import math
import os
import sys

EXTEND_FACTOR = 0.7        # next tau below the finest / above the coarsest run
TAU_MIN, TAU_MAX = 0.004, 1.0
FIGURES = ("excess", "iou")


def read_peers(path):
    rows = []
    lines = [l.rstrip("\n") for l in open(path) if not l.startswith("#") and l.strip()]
    head = lines[0].split("\t")
    for line in lines[1:]:
        r = dict(zip(head, line.split("\t")))
        if r["iou"] == "n/a":
            r["open"] = True
        else:
            r["open"] = False
            for k in ("parts", "iou", "excess"):
                r[k] = float(r[k])
        rows.append(r)
    return rows


def read_runs(results, model):
    runs = []
    base = os.path.join(results, model)
    if not os.path.isdir(base):
        return runs
    for d in os.listdir(base):
        p = os.path.join(base, d)
        try:
            rep = json.load(open(os.path.join(p, "report.json")))
            ev = json.load(open(os.path.join(p, "eval.json")))
            rc = int(open(os.path.join(p, "rc")).read())
        except (OSError, ValueError):
            continue   # incomplete or failed run
        if rc not in (0, 4):
            continue
        commit = open(os.path.join(p, "commit")).read().strip() if os.path.exists(os.path.join(p, "commit")) else "?"
        runs.append({"tau": rep["parameters"]["tau"], "parts": len(rep["components"]),
                     "excess": max(ev["hull_outside_max"], ev["model_to_hulls_max"]),
                     "iou": ev["iou"], "seconds": rep["timing"]["total_seconds"],
                     "unresolved": rep["totals"].get("unresolved", 0), "rc": rc, "commit": commit})
    return sorted(runs, key=lambda r: -r["tau"])


def better(figure, a, b):
    """True when value a is strictly better than b for this figure."""
    return a < b if figure == "excess" else a > b


def meets(figure, value, target):
    return value <= target if figure == "excess" else value >= target


def envelope(runs, figure):
    front = []
    for r in sorted(runs, key=lambda r: (r["parts"], r[figure] if figure == "excess" else -r[figure])):
        if not front or better(figure, r[figure], front[-1][figure]):
            front.append(r)   # (a tie in parts comes after its best run, so is never kept)
    return front


def parts_at(runs, figure, target):
    """(parts, note, bracketing runs): parts interpolated at the target; note '<=' or '>' when
    the runs do not bracket it (parts is then the bound)."""
    front = envelope(runs, figure)
    if not front:
        return None, "no runs", []
    i = next((k for k, r in enumerate(front) if meets(figure, r[figure], target)), None)
    if i is None:
        return front[-1]["parts"], ">", [front[-1]]
    if i == 0:
        return front[0]["parts"], "<=", [front[0]]
    lo, hi = front[i - 1], front[i]
    w = (target - lo[figure]) / (hi[figure] - lo[figure])
    return math.exp(math.log(lo["parts"]) + w * (math.log(hi["parts"]) - math.log(lo["parts"]))), "", [lo, hi]


def closed_peers(peers, models):
    return [p for p in peers if p["model"] in models and not p["open"]]


def extend(results, peers, models):
    """Taus to add so that every peer figure is bracketed (each call: one step per model)."""
    for m in models:
        runs = read_runs(results, m)
        if not runs:
            continue
        taus = [r["tau"] for r in runs]
        want = set()
        for p in closed_peers(peers, [m]):
            for f in FIGURES:
                _, note, _ = parts_at(runs, f, p[f])
                if note == ">" and min(taus) * EXTEND_FACTOR >= TAU_MIN:
                    want.add(min(taus) * EXTEND_FACTOR)
                elif note == "<=" and min(r["parts"] for r in runs) > 1 and max(taus) / EXTEND_FACTOR <= TAU_MAX:
                    want.add(max(taus) / EXTEND_FACTOR)
        for t in sorted(want):
            print(m, "%.3g" % t)


def fmt_parts(v, note, brackets):
    if v is None:
        return "–"
    s = ("%s %d" % (note, v)) if note else "%.1f" % v
    if any(r["rc"] == 4 for r in brackets):
        s += " †"
    return s


def geomean(xs):
    return "%.2f" % math.exp(sum(math.log(x) for x in xs) / len(xs)) if xs else "–"


def table(results, peers, models):
    out = []
    rows_tsv = ["model\ttau\tparts\texcess\tiou\tseconds\tunresolved\trc\tcommit"]
    ratios = {}       # (tool, setting, figure) -> [ratio]
    default_verdict = []
    commits = set()
    out.append("| model | peer | peer parts | peer excess | peer IoU | acd parts at excess | ratio | acd parts at IoU | ratio |")
    out.append("|---|---|---:|---:|---:|---:|---:|---:|---:|")
    for m in models:
        runs = read_runs(results, m)
        for r in sorted(runs, key=lambda r: -r["tau"]):
            commits.add(r["commit"])
            rows_tsv.append("%s\t%g\t%d\t%.4f\t%.4f\t%.2f\t%d\t%d\t%s" % (
                m, r["tau"], r["parts"], r["excess"], r["iou"], r["seconds"], r["unresolved"], r["rc"], r["commit"]))
        for p in closed_peers(peers, [m]):
            cells, rs = [], {}
            for f in FIGURES:
                v, note, br = parts_at(runs, f, p[f])
                ratio = v / p["parts"] if v is not None else None
                if ratio is not None and not note:
                    ratios.setdefault((p["tool"], p["setting"], f), []).append(ratio)
                    rs[f] = ratio
                cells += [fmt_parts(v, note, br), "%.2f" % ratio if ratio is not None and not note else "–"]
            out.append("| %s | %s %s | %d | %.3f | %.3f | %s |" % (
                m, p["tool"], p["setting"], p["parts"], p["excess"], p["iou"], " | ".join(cells)))
            if p["tool"] == "CoACD" and p["setting"] == "t=0.05":
                worse = [f for f in FIGURES if rs.get(f, 0) > 1]
                default_verdict.append((m, rs, worse))
    skipped = sorted({p["model"] for p in peers if p["open"] and p["model"] in models})
    out.append("")
    out.append("Geometric means of acd parts / peer parts (pairs bracketed by acd runs; n = pairs):")
    out.append("")
    out.append("| peer | at excess | acd fewer | at IoU | acd fewer |")
    out.append("|---|---:|---:|---:|---:|")
    keys = [k for k in dict.fromkeys((p["tool"], p["setting"]) for p in peers) if any(k + (f,) in ratios for f in FIGURES)]
    for group in [[k for k in keys if k[0] == "CoACD"], [k for k in keys if k[0] != "CoACD"]]:
        for t, s in group:
            cell = []
            for f in FIGURES:
                xs = ratios.get((t, s, f), [])
                cell += ["%s (n = %d)" % (geomean(xs), len(xs)), "%d of %d" % (sum(x < 1 for x in xs), len(xs))]
            out.append("| %s %s | %s |" % (t, s, " | ".join(cell)))
        if group and group[0][0] == "CoACD":
            allx = {f: [x for (t, s, g), xs in ratios.items() if t == "CoACD" and g == f for x in xs] for f in FIGURES}
            cell = []
            for f in FIGURES:
                cell += ["**%s** (n = %d)" % (geomean(allx[f]), len(allx[f])),
                         "**%d of %d**" % (sum(x < 1 for x in allx[f]), len(allx[f]))]
            out.append("| **CoACD, all settings** | %s |" % " | ".join(cell))
    out.append("")
    out.append("Against CoACD's default (t = 0.05), per model (ratio > 1: acd needs more parts):")
    out.append("")
    for m, rs, worse in default_verdict:
        r = ", ".join("%s %s" % (f, "%.2f" % rs[f] if f in rs else "not bracketed") for f in FIGURES)
        out.append("- %s: %s (%s)" % (m, ("**worse** at " + " and ".join(worse)) if worse else "not worse", r))
    out.append("")
    notes = ["† a bracketing run left some component unresolved (decompose exit 4).",
             "`<= N`: even acd's coarsest run meets the figure; `> N`: even its finest misses it (not in the means)."]
    if skipped:
        notes.append("Open models skipped (no inside, so no IoU or excess): " + ", ".join(skipped) + ".")
    notes.append("acd commit(s) measured: " + ", ".join(sorted(commits)) + ".")
    out += notes
    open(os.path.join(results, "runs.tsv"), "w").write("\n".join(rows_tsv) + "\n")
    print("\n".join(out))


if __name__ == "__main__":
    mode, results, peers_path, models = sys.argv[1], sys.argv[2], sys.argv[3], sys.argv[4:]
    peers = read_peers(peers_path)
    {"extend": extend, "table": table}[mode](results, peers, models)

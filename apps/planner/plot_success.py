#!/usr/bin/python3
"""Success rate against the number of samples, one line per sampler, from the sweep.csv
that `planner SCENARIO --sweep` writes. Usage: plot_success.py SWEEP_CSV OUT_PNG [TITLE]"""
import csv
import sys
from collections import defaultdict

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def main():
    if len(sys.argv) < 3:
        sys.exit("usage: plot_success.py SWEEP_CSV OUT_PNG [TITLE]")
    rows = defaultdict(list)
    trials = set()
    with open(sys.argv[1], newline="") as f:
        for r in csv.DictReader(f):
            rows[r["sampler"]].append(
                (int(r["samples"]), float(r["rate"]), float(r["ci_low"]), float(r["ci_high"])))
            trials.add(int(r["trials"]))
    fig, ax = plt.subplots(figsize=(7, 4.5), dpi=120)
    for name, points in rows.items():
        points.sort()
        n = [p[0] for p in points]
        rate = [100 * p[1] for p in points]
        lo = [100 * p[2] for p in points]
        hi = [100 * p[3] for p in points]
        line, = ax.plot(n, rate, marker="o", label=name)
        ax.fill_between(n, lo, hi, color=line.get_color(), alpha=0.12)
    all_n = [p[0] for points in rows.values() for p in points]
    if all_n and max(all_n) > 20 * min(all_n):  # a doubling search: equal steps on a log axis
        ax.set_xscale("log")
    ax.set_xlabel("sampled milestones N")
    ax.set_ylabel("success rate [%] (start and goal connected)")
    ax.set_ylim(-2, 102)
    title = sys.argv[3] if len(sys.argv) > 3 else "PRM success against the number of samples"
    ax.set_title(title + " (%s trials per point, 95%% Wilson bands)" % "/".join(str(t) for t in sorted(trials)),
                 fontsize=9)
    ax.grid(True, alpha=0.3)
    ax.legend()
    fig.tight_layout()
    fig.savefig(sys.argv[2])


if __name__ == "__main__":
    main()

#!/usr/bin/python3
"""Share of runs solved against time, one line per planner, from the race_runs.csv that
`planner PROBLEM --race` writes (unsolved runs never count). Usage:
plot_race.py RACE_RUNS_CSV OUT_PNG [TITLE]"""
import csv
import sys
from collections import defaultdict

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def main():
    if len(sys.argv) < 3:
        sys.exit("usage: plot_race.py RACE_RUNS_CSV OUT_PNG [TITLE]")
    runs = defaultdict(list)
    with open(sys.argv[1], newline="") as f:
        for r in csv.DictReader(f):
            runs[r["planner"]].append((r["solved"] == "1", float(r["seconds"])))
    limit = max(s for rs in runs.values() for _, s in rs)
    fig, ax = plt.subplots(figsize=(7, 4.5), dpi=120)
    for name, rs in runs.items():
        times = sorted(s for ok, s in rs if ok)
        xs, ys = [0.0], [0.0]
        for i, t in enumerate(times):
            xs += [t, t]
            ys += [100.0 * i / len(rs), 100.0 * (i + 1) / len(rs)]
        xs.append(limit)
        ys.append(ys[-1])
        ax.plot(xs, ys, label=name, linewidth=2.5 if name == "PRM_acd" else 1.2)
    ax.set_xlabel("seconds (PRM_acd: ACD preprocessing included)")
    ax.set_ylabel("runs solved [%]")
    ax.set_ylim(-2, 102)
    ax.set_xscale("symlog", linthresh=0.1)
    ax.set_xlim(left=0)  # no negative times on the axis
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize=7, ncol=2)
    if len(sys.argv) > 3:
        ax.set_title(sys.argv[3])
    fig.tight_layout()
    fig.savefig(sys.argv[2])


if __name__ == "__main__":
    main()

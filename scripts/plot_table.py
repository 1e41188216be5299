#!/usr/bin/python3
"""Plots of `acd-table --json FILE` (the analogues of the paper's Figures 18-19 and Table 1).

usage: /usr/bin/python3 scripts/plot_table.py TABLE.json [--out docs/images]

Writes plot-solid-sweep.png and plot-surface-sweep.png (components and time against tau, with
and without feature grouping; only when the JSON has a sweep of that kind) and
plot-table-components.png (components per model and method, log scale).
"""
import argparse
import json
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def usable(run):
    return run.get("status") in ("ok", "unresolved") and run.get("components", -1) > 0


def plot_sweep(table, kind, path):
    runs = [r for r in table.get("sweep", []) if r["kind"] == kind and usable(r)]
    if not runs:
        return False
    models = sorted({r["model"] for r in runs})
    fig, (ax_n, ax_t) = plt.subplots(1, 2, figsize=(11, 4.2))
    colours = plt.rcParams["axes.prop_cycle"].by_key()["color"]
    for i, model in enumerate(models):
        for grouping in (True, False):
            pts = sorted((r["tau"], r["components"], r["seconds"]) for r in runs
                         if r["model"] == model and r["grouping"] == grouping)
            if not pts:
                continue
            taus, comps, secs = zip(*pts)
            style = dict(color=colours[i % len(colours)], marker="o" if grouping else "s",
                         linestyle="-" if grouping else "--",
                         label=f"{model}, {'with' if grouping else 'without'} grouping")
            ax_n.plot(taus, comps, **style)
            ax_t.plot(taus, secs, **style)
        # The exact decomposition of the same model, where it finished: the limit tau -> 0 aims at.
        for row in table.get("models", []):
            ecd = row.get("runs", {}).get(f"{kind}_ecd", {})
            if row["model"] == model and usable(ecd):
                ax_n.axhline(ecd["components"], color=colours[i % len(colours)], linestyle=":",
                             label=f"{model}, {kind} ECD")
                ax_t.axhline(ecd["seconds"], color=colours[i % len(colours)], linestyle=":")
    for ax, label in ((ax_n, "components"), (ax_t, "time (s)")):
        ax.set_xscale("log")
        ax.invert_xaxis()  # finer approximations to the right, as tau shrinks
        ax.set_xlabel("τ (concavity tolerance, normalised units)")
        ax.set_ylabel(label)
        ax.grid(True, which="both", alpha=0.3)
    ax_n.set_yscale("log")
    ax_t.set_yscale("log")
    ax_n.legend(fontsize=7)
    fig.suptitle(f"{kind} ACD: size and time against τ")
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)
    return True


def plot_table(table, path):
    rows = table.get("models", [])
    if not rows:
        return False
    def order(key):  # solid before surface, coarse tau before fine, the exact one last
        kind, method = key.split("_")[0], key.split("_")[1]
        tau = float(key.split("_")[2]) if method == "acd" else 0.0
        return (kind != "solid", method == "ecd", -tau)

    keys = sorted(rows[0]["runs"].keys(), key=order)
    fig, ax = plt.subplots(figsize=(max(7, 1.1 * len(rows) + 3), 4.5))
    width = 0.8 / len(keys)
    for k, key in enumerate(keys):
        xs, ys = [], []
        for i, row in enumerate(rows):
            run = row["runs"][key]
            if usable(run):
                xs.append(i + (k - (len(keys) - 1) / 2) * width)
                ys.append(run["components"])
        if xs:
            ax.bar(xs, ys, width, label=key.replace("_", " ").replace("acd ", "ACD τ=").replace("ecd", "ECD"))
    ax.set_yscale("log")
    ax.set_xticks(range(len(rows)))
    ax.set_xticklabels([r["model"] for r in rows], rotation=30, ha="right")
    ax.set_ylabel("components (log scale)")
    ax.set_title("components per decomposition (missing bar: not finished, refused or not available)")
    ax.legend(fontsize=7, ncol=2)
    ax.grid(True, axis="y", which="both", alpha=0.3)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)
    return True


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("table", help="JSON written by `acd-table --json`")
    parser.add_argument("--out", default="docs/images", help="folder of the PNG files")
    a = parser.parse_args()
    with open(a.table) as f:
        table = json.load(f)
    os.makedirs(a.out, exist_ok=True)
    made = []
    for kind in ("solid", "surface"):
        p = os.path.join(a.out, f"plot-{kind}-sweep.png")
        if plot_sweep(table, kind, p):
            made.append(p)
    p = os.path.join(a.out, "plot-table-components.png")
    if plot_table(table, p):
        made.append(p)
    if not made:
        print("plot_table.py: nothing to plot in " + a.table, file=sys.stderr)
        return 1
    for p in made:
        print(p)
    return 0


if __name__ == "__main__":
    sys.exit(main())

#!/usr/bin/python3
"""acd against CoACD and V-HACD on meshes of many shells (CAD assemblies), run side by side with
the same cache, peers and evaluators as bench/compare_peers.py.

  compare_assemblies.py run   [--only acd|peers|all] [--models A,B] [--shard I/N] [--existing] [--acd-flags=F]
  compare_assemblies.py table [--models A,B]            -> Markdown on stdout

The meshes, chosen by rule before any result was seen:
- every file of the wide data set's develop/ whose mesh has two or more edge-connected pieces
  (`acd info`'s `components`), as it is (scene files merged);
- the assemblies bench/assemblies/generate.py makes (36 at seed 1, generated once into the cache);
- the held-out single-body parts of compare/ (their runs are shared with compare_peers.py).
acd runs at a fixed tau list, CoACD at -t 0.05 and 0.02 (seed 0), V-HACD at its defaults. Scores
come from acd-score (CGAL only, no libacd code): hull count, how far the hulls stand outside the
input (maximum and 99th percentile of hull-surface samples), how far the input reaches outside
the hulls, volume IoU (the solid inside any shell), wall time. acd's hull count at a peer's
figure is interpolated between adjacent tau by bench/fidelity.py's rules.
"""
import argparse
import glob
import json
import os
import re
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import compare_peers as cp  # noqa: E402
import fidelity  # noqa: E402

# acd's series here, fixed before looking at results: compare_peers' list between 0.07 and
# 0.0175, around the peers' settings at 0.05 and 0.02, and both of them (the table's acd columns).
ACD_TAUS = [0.07, 0.05, 0.035, 0.025, 0.02, 0.0175]
PEERS = [("vhacd-default", "vhacd", []),  # cheap first: a cold run stopped early has it everywhere
         ("coacd-t0.05-s0", "coacd", ["-t", "0.05", "-s", "0"]),
         ("coacd-t0.02-s0", "coacd", ["-t", "0.02", "-s", "0"])]
GENERATED = dict(count=36, seed=1)
SIMULATOR_LIMIT = 64  # hulls per body a GPU simulator (PhysX) takes


def shells_of(paths, model):
    p = subprocess.run([paths.acd, "info", model], capture_output=True, text=True)
    m = re.search(r"^\s*components\s+(\d+)", p.stdout, re.M)
    return int(m.group(1)) if m else 0


def generated_dir(paths):
    d = os.path.join(paths.cache, "assemblies", "seed%(seed)d-n%(count)d" % GENERATED)
    if not os.path.exists(os.path.join(d, "manifest.tsv")):
        cp.ensure_packages(["openscad", "openscad-mcad"], "the assembly generator's packages")
        cp.say("generating %(count)d assemblies (seed %(seed)d) with OpenSCAD" % GENERATED)
        subprocess.run([os.path.join(cp.ROOT, "bench/assemblies/generate.py"), d, "--count", str(GENERATED["count"]),
                        "--seed", str(GENERATED["seed"])], check=True)
    return d


def models_of(paths, only=None):
    """[(name, path, set)] in a fixed order."""
    out = []
    for p in sorted(glob.glob(os.path.join(paths.wide, "develop/*"))):
        if shells_of(paths, p) >= 2:
            out.append((os.path.basename(p), p, "develop, multi-body"))
    for p in sorted(glob.glob(os.path.join(generated_dir(paths), "*.stl")) +
                    glob.glob(os.path.join(generated_dir(paths), "*.obj"))):
        out.append((os.path.basename(p), p, "generated assembly"))
    for p in sorted(glob.glob(os.path.join(paths.wide, "compare/*"))):
        out.append((os.path.splitext(os.path.basename(p))[0], p, "compare, single body"))
    if only:
        out = [m for m in out if m[0] in only]
    return out


def scorable(paths, model):
    """The model as the evaluators read it: the peers' OBJ (acd's own writer; scene files merged),
    since acd-score reads with CGAL, which reads no glTF, COLLADA or 3MF."""
    return cp.peer_input(paths, model)


def run(args, paths):
    models = models_of(paths, args.models)
    if args.only in ("acd", "all"):
        for name, model, _ in models:
            for tau in ACD_TAUS:
                cp.say("acd %s tau %g" % (name, tau))
                d = cp.run_acd(paths, model, tau, flags=args.acd_flags)  # --existing spares the peers only
                dst = os.path.join(paths.out, name, "acd-t%g" % tau)
                cp.publish(d, dst, ["hulls.obj", "report.json", "log.txt", "run.json"])
                if os.path.exists(os.path.join(d, "hulls.obj")):
                    cp.publish(cp.evaluate(paths, scorable(paths, model), os.path.join(d, "hulls.obj"), with_acd=False),
                               dst, ["score.json"])
    if args.only in ("peers", "all"):
        cp.ensure_peers(paths)
        shard, shards = args.shard
        jobs = [(label, tool, flags, name, model) for label, tool, flags in PEERS for name, model, _ in models
                if not args.peers or label in args.peers]
        for label, tool, flags, name, model in jobs[shard::shards]:
            if not args.existing:
                cp.say("%s %s" % (label, name))
            d = cp.run_peer(paths, cp.peer_input(paths, model), tool, flags, args.existing)
            if d is None:
                continue
            dst = os.path.join(paths.out, name, label)
            cp.publish(d, dst, ["hulls.obj", "log.txt", "run.json"])
            if os.path.exists(os.path.join(d, "hulls.obj")):
                cp.publish(cp.evaluate(paths, scorable(paths, model), os.path.join(d, "hulls.obj"), with_acd=False),
                           dst, ["score.json"])


# ---- the tables -------------------------------------------------------------------------------

def scored(d):
    """acd-score's figures of one published run, with its exit code and time; None if absent."""
    try:
        runinfo = json.load(open(os.path.join(d, "run.json")))
    except (OSError, ValueError):
        return None
    f = {"rc": runinfo["rc"], "seconds": runinfo["seconds"]}
    try:
        s = json.load(open(os.path.join(d, "score.json")))
    except (OSError, ValueError):
        s = {"error": "no hulls"}
    if "error" in s:
        f["error"] = s["error"]
        return f
    f.update(parts=s["hulls"], out_max=s["hull_outside_max"], out_p99=s["hull_outside_p99"],
             uncovered=s["model_to_hulls_max"], iou=s["iou"])
    f["excess"] = max(f["out_max"], f["uncovered"])
    return f


def acd_series(out, name):
    s = []
    for tau in ACD_TAUS:
        f = scored(os.path.join(out, name, "acd-t%g" % tau))
        if f and "error" not in f:
            s.append(dict(f, tau=tau))
    return s


def cell(f):
    if f is None:
        return "–"
    if "error" in f:
        return "exit %d, not scored" % f["rc"] if f["rc"] != 0 else "not scored"
    rc = "" if f["rc"] == 0 else " (exit %d)" % f["rc"]
    iou = "–" if f["iou"] is None else "%.3f" % f["iou"]
    return "%d · %.3f / %.3f · %.3f · %s · %.1f s%s" % (f["parts"], f["out_max"], f["out_p99"], f["uncovered"], iou,
                                                    f["seconds"], rc)


def table(args, paths):
    models = models_of(paths, args.models)
    out = paths.out
    print("Each cell: hulls · hull-to-input distance max / 99th percentile · input outside the hulls · IoU · "
          "wall time (distances in the model's normalised units; acd-score).\n")
    print("| model | set | acd τ 0.05 | CoACD t 0.05 | acd τ 0.02 | CoACD t 0.02 | V-HACD default |")
    print("|---|---|---|---|---|---|---|")
    ratios = {"0.05": [], "0.02": []}
    kinds = {"0.05": [], "0.02": []}
    beyond, over64 = [], []
    for name, _, group in models:
        a05 = scored(os.path.join(out, name, "acd-t0.05"))
        a02 = scored(os.path.join(out, name, "acd-t0.02"))
        c05 = scored(os.path.join(out, name, "coacd-t0.05-s0"))
        c02 = scored(os.path.join(out, name, "coacd-t0.02-s0"))
        v = scored(os.path.join(out, name, "vhacd-default"))
        print("| %s | %s | %s | %s | %s | %s | %s |" % (name, group, cell(a05), cell(c05), cell(a02), cell(c02), cell(v)))
        series = acd_series(out, name)
        for t, c in (("0.05", c05), ("0.02", c02)):
            if c and "error" not in c and series:
                r, kind = fidelity.ratio(series, "excess", c["parts"], c["excess"])
                ratios[t].append(r)
                kinds[t].append(kind)
        for tau, a in ((0.05, a05), (0.02, a02)):
            if a and "error" not in a and a["out_max"] > tau * 1.05 and a["rc"] == 0:
                beyond.append("%s at τ %g (%.3f, exit 0)" % (name, tau, a["out_max"]))
        if a05 and c05 and "error" not in a05 and "error" not in c05 and c05["parts"] <= SIMULATOR_LIMIT < a05["parts"]:
            over64.append("%s (%d; CoACD %d)" % (name, a05["parts"], c05["parts"]))
    print()
    print("| CoACD setting | pairs | acd / CoACD hulls at equal hull-to-input distance (geometric mean) | acd fewer | upper bounds | not bracketed (losses) |")
    print("|---|---:|---:|---:|---:|---:|")
    for t in ("0.05", "0.02"):
        xs = ratios[t]
        print("| t %s | %d | %s | %d | %d | %d |" % (t, len(xs), "%.2f" % fidelity.geomean(xs) if xs else "–",
                                                 sum(x < 1 for x in xs), kinds[t].count(fidelity.AT_MOST),
                                                 kinds[t].count(fidelity.LOSS)))
    print()
    print("acd hulls beyond τ (acd-score, 5%% sampling allowance) with exit 0: %s." % (", ".join(beyond) or "none"))
    print("acd above %d hulls at τ 0.05 where CoACD needs at most %d: %s." % (SIMULATOR_LIMIT, SIMULATOR_LIMIT,
                                                                         ", ".join(over64) or "none"))


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("mode", choices=["run", "table"])
    ap.add_argument("--models", type=lambda s: s.split(","), default=None)
    ap.add_argument("--only", choices=["acd", "peers", "all"], default="all")
    ap.add_argument("--out", default=os.path.join(cp.ROOT, "out/compare_assemblies"))
    ap.add_argument("--acd-flags", type=lambda s: s.split(), default=[],
                    help="more flags for every acd run, e.g. --acd-flags=--union (with its own --out)")
    ap.add_argument("--peers", type=lambda s: s.split(","), default=None,
                    help="only these peer runs, e.g. coacd-t0.02-s0 (default: all of them)")
    ap.add_argument("--existing", action="store_true", help="publish and score only the peer runs already in the cache (acd always runs)")
    ap.add_argument("--shard", type=lambda s: tuple(int(x) for x in s.split("/")), default=(0, 1),
                    help="I/N: run only every N-th peer run from the I-th")
    args = ap.parse_args()
    paths = cp.Paths(args.out)
    (run if args.mode == "run" else table)(args, paths)


if __name__ == "__main__":
    main()

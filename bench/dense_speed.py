#!/usr/bin/python3
"""acd against V-HACD's defaults on time and peak memory, from the corpus up to dense inputs of
about a million faces.

  bench/dense_speed.py [--tau 0.05] [--repeat 3] [--models A,B] [--acd-flags="--working-share 0"] [--out DIR]
                                                                              -> Markdown on stdout

The dense inputs are made here, by midpoint subdivision (every triangle into four, the same
shape): armadillo x1 and x2 (208k, 832k faces), bunny00 x1 and x2 (300k, 1.2M), ChineseDragon-10kv
x2 (320k). V-HACD is built from ../shared/peers as bench/compare_peers.sh builds it. Each input is
run REPEAT times as acd, V-HACD, acd, V-HACD, ... (alternating, so that a busy spell of a shared
machine hits both), each run the whole process: `acd decompose MODEL.off -t TAU -q --threads 2`
and `vhacd MODEL.obj` (its defaults), wall time and peak resident memory from wait4. The table
gives medians with the spread (min-max) and acd / V-HACD of the medians.
"""
import argparse
import json
import os
import statistics
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import compare_peers as cp  # noqa: E402

import numpy as np  # noqa: E402

# (name, corpus model, subdivisions), fixed before any run.
DENSE = [("armadillo-x1", "armadillo", 1), ("armadillo-x2", "armadillo", 2), ("bunny00-x1", "bunny00", 1),
         ("bunny00-x2", "bunny00", 2), ("ChineseDragon-x2", "ChineseDragon-10kv", 2)]


def read_off(path):
    with open(path) as f:
        tokens = [t for line in f for t in line.split("#")[0].split()]
    assert tokens[0] == "OFF", path
    nv, nf = int(tokens[1]), int(tokens[2])
    v = np.array(tokens[4:4 + 3 * nv], dtype=float).reshape(nv, 3)
    rest = np.array(tokens[4 + 3 * nv:], dtype=np.int64)
    faces, k = [], 0
    for _ in range(nf):
        n = rest[k]
        assert n == 3, "triangles only"
        faces.append(rest[k + 1:k + 4])
        k += n + 1
    return v, np.array(faces)


def write_off(path, v, f):
    with open(path, "w") as out:
        out.write("OFF\n%d %d 0\n" % (len(v), len(f)))
        np.savetxt(out, v, fmt="%.9g")
        np.savetxt(out, np.hstack([np.full((len(f), 1), 3), f]), fmt="%d")


def subdivide(v, f):
    """Midpoint subdivision: a new vertex at each edge's middle, each triangle into four."""
    edges = np.sort(np.concatenate([f[:, [0, 1]], f[:, [1, 2]], f[:, [2, 0]]]), axis=1)
    unique, inverse = np.unique(edges, axis=0, return_inverse=True)
    mid = len(v) + inverse.reshape(3, len(f)).T  # the middles of edges 01, 12, 20 of each face
    v2 = np.vstack([v, (v[unique[:, 0]] + v[unique[:, 1]]) / 2])
    a, b, c = f[:, 0], f[:, 1], f[:, 2]
    ab, bc, ca = mid[:, 0], mid[:, 1], mid[:, 2]
    f2 = np.vstack([np.stack([a, ab, ca], 1), np.stack([ab, b, bc], 1), np.stack([ca, bc, c], 1),
                    np.stack([ab, bc, ca], 1)])
    return v2, f2


def dense_input(paths, name, model, times):
    src = os.path.join(cp.ROOT, "data/meshes/%s.off" % model)
    key = cp.key_of("dense", cp.fixed_file_hash(src), str(times))

    def make(d):
        v, f = read_off(src)
        for _ in range(times):
            v, f = subdivide(v, f)
        write_off(os.path.join(d, name + ".off"), v, f)

    return os.path.join(cp.cached(paths, key, make), name + ".off")


def faces_of(path):
    with open(path) as f:
        f.readline()
        return int(f.readline().split()[1])


def run_once(paths, tool, model, obj, tau, work, acd_flags=()):
    d = tempfile.mkdtemp(dir=work)
    if tool == "acd":
        cmd = [paths.acd, "decompose", model, "-t", str(tau), "-o", d, "-q", "--threads", "2"] + list(acd_flags)
    else:
        os.symlink(obj, os.path.join(d, "model.obj"))
        cmd = [paths.peer("vhacd"), "model.obj"]
    rc, sec, mb = cp.timed(cmd, d, os.path.join(d, "log.txt"), cp.PEER_TIMEOUT)
    parts = None
    if tool == "acd" and rc == 0:
        parts = len(json.load(open(os.path.join(d, "report.json")))["components"])
    elif tool == "vhacd" and rc == 0:
        parts = sum(1 for line in open(os.path.join(d, "decomp.obj")) if line.startswith("o "))
    os.system("rm -rf '%s'" % d)
    return {"rc": rc, "seconds": sec, "peak_mb": mb, "parts": parts}


def spread(runs, key):
    xs = [r[key] for r in runs]
    return statistics.median(xs), min(xs), max(xs)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--tau", type=float, default=0.05)
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--models", default="", help="comma-separated names (corpus models or the dense names above)")
    ap.add_argument("--acd-flags", default="", help="more flags for acd decompose, written --acd-flags=\"...\"")
    ap.add_argument("--out", default=os.path.join(cp.ROOT, "out/dense_speed"))
    args = ap.parse_args()
    args.out = os.path.abspath(args.out)  # the runs' working folder is their own
    paths = cp.Paths(args.out)
    cp.ensure_peers(paths, ("vhacd",))
    os.makedirs(args.out, exist_ok=True)
    inputs = [(m, os.path.join(cp.ROOT, "data/meshes/%s.off" % m)) for m in cp.CORPUS]
    inputs += [(name, None, model, times) for name, model, times in DENSE]
    only = set(filter(None, args.models.split(",")))
    rows = []
    for entry in inputs:
        name = entry[0]
        if only and name not in only:
            continue
        model = entry[1] if entry[1] else dense_input(paths, name, entry[2], entry[3])
        obj = cp.peer_input(paths, model)
        runs = {"acd": [], "vhacd": []}
        for r in range(args.repeat):
            for tool in ("acd", "vhacd"):
                cp.say("%s: %s run %d/%d" % (name, tool, r + 1, args.repeat))
                runs[tool].append(run_once(paths, tool, model, obj, args.tau, args.out, args.acd_flags.split()))
        rows.append((name, faces_of(model), runs))
        json.dump(rows, open(os.path.join(args.out, "runs.json"), "w"), indent=1)
    if args.acd_flags:
        print("acd with `%s`.\n" % args.acd_flags)
    print("| model | faces | acd s | V-HACD s | acd / V-HACD | acd MB | V-HACD MB | acd parts | V-HACD parts |")
    print("|---|---:|---:|---:|---:|---:|---:|---:|---:|")
    for name, faces, runs in rows:
        failed = [t for t in runs if any(r["rc"] != 0 for r in runs[t])]
        if failed:
            print("| %s | %d | %s |" % (name, faces, "FAILED: " + ", ".join(failed)))
            continue
        a, v = spread(runs["acd"], "seconds"), spread(runs["vhacd"], "seconds")
        am, vm = spread(runs["acd"], "peak_mb"), spread(runs["vhacd"], "peak_mb")
        print("| %s | %d | %.2f (%.2f-%.2f) | %.2f (%.2f-%.2f) | %.2f | %.0f | %.0f | %d | %d |" % (
            name, faces, *a, *v, a[0] / v[0], am[0], vm[0], runs["acd"][0]["parts"], runs["vhacd"][0]["parts"]))


if __name__ == "__main__":
    main()

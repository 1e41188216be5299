#!/usr/bin/python3
"""acd against CoACD and V-HACD, built from source and run side by side on the same inputs
(bench/compare_peers.sh is the command; docs/BENCHMARKS.md states the rules, bench/fidelity.py
holds them).

  compare_peers.py run   [--set corpus|heldout|all] [--models A,B] [--only acd|peers|all]
  compare_peers.py table [--set ...] [--models ...]           -> Markdown on stdout

Every run lands in a cache outside the repository ($ACD_BENCH_CACHE, default
~/.cache/acd-bench), keyed by the SHA-256 of its input, its binary and its flags: a re-run after
an acd change runs only acd, and a cold run may be stopped and resumed at any point. The peers'
own files (hulls, log) and both evaluators' scores are copied beside each other into OUT
(default out/compare_peers)/MODEL/TOOL-SETTING/.
"""
import argparse
import functools
import glob
import hashlib
import json
import os
import shutil
import subprocess
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import fidelity  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
CORPUS = ["armadillo", "bunny00", "camel", "cow", "dino", "eight", "elephant", "handle", "homer", "knot"]
# acd's one series, fixed before looking at any result: factors of about 0.7 from 0.2 down.
ACD_TAUS = [0.2, 0.14, 0.1, 0.07, 0.05, 0.035, 0.025, 0.0175, 0.0125, 0.00875]
COACD_T = [0.1, 0.05, 0.02]
COACD_SEEDS = [0, 1, 2]
VHACD_SETTINGS = [("default", []), ("h128", ["-h", "128"])]
SAMPLES = 1_000_000
PEER_TIMEOUT = 1800  # s: a peer run beyond it is recorded as failed


def say(msg):
    print("[compare_peers %s] %s" % (time.strftime("%H:%M:%S"), msg), file=sys.stderr, flush=True)


def sha256(path):
    h = hashlib.sha256()
    with open(path, "rb") as f:
        for block in iter(lambda: f.read(1 << 20), b""):
            h.update(block)
    return h.hexdigest()


# Binaries and models do not change during a run: hash each once (hull files are hashed each time).
fixed_file_hash = functools.lru_cache(maxsize=None)(sha256)


def key_of(*parts):
    return hashlib.sha256("\n".join(parts).encode()).hexdigest()[:24]


class Paths:
    def __init__(self, out):
        self.cache = os.environ.get("ACD_BENCH_CACHE", os.path.expanduser("~/.cache/acd-bench"))
        self.out = out
        self.acd = os.path.join(ROOT, "build/bin/acd")
        self.score = os.path.join(ROOT, "build/bin/acd-score")
        self.peers_bin = os.path.join(self.cache, "peers-build/bin")
        self.peers_src = os.environ.get("ACD_PEERS_SRC", os.path.join(os.path.dirname(ROOT), "shared/peers"))
        self.wide = os.environ.get("ACD_WIDE_DATA", os.path.join(os.path.dirname(ROOT), "shared/datasets/wide"))

    def peer(self, tool):
        return os.path.join(self.peers_bin, tool)


def models_of(paths, which, only):
    """[(name, path, set)] in a fixed order."""
    out = []
    if which in ("corpus", "all"):
        out += [(m, os.path.join(ROOT, "data/meshes/%s.off" % m), "corpus") for m in CORPUS]
    if which in ("heldout", "all"):
        for p in sorted(glob.glob(os.path.join(paths.wide, "compare/*"))):
            out.append((os.path.splitext(os.path.basename(p))[0], p, "heldout"))
    if only:
        out = [m for m in out if m[0] in only]
    return out


def timed(cmd, cwd, log_path, timeout):
    """Runs cmd; returns (exit code, wall seconds, peak resident MB) with stdout+stderr in log_path."""
    start = time.monotonic()
    with open(log_path, "w") as log:
        p = subprocess.Popen(cmd, cwd=cwd, stdout=log, stderr=subprocess.STDOUT)
        deadline = start + timeout
        while True:
            pid, status, usage = os.wait4(p.pid, os.WNOHANG)
            if pid:
                break
            if time.monotonic() > deadline:
                p.kill()
                pid, status, usage = os.wait4(p.pid, 0)
                return -9, time.monotonic() - start, usage.ru_maxrss / 1024
            time.sleep(0.05)
    rc = os.waitstatus_to_exitcode(status)
    return rc, time.monotonic() - start, usage.ru_maxrss / 1024


def cached(paths, key, make, existing_only=False):
    """The cache folder for key, made by make(dir) once (a folder without `done` is re-made);
    with existing_only, None instead of making it."""
    d = os.path.join(paths.cache, "runs", key)
    if os.path.exists(os.path.join(d, "done")):
        return d
    if existing_only:
        return None
    shutil.rmtree(d, ignore_errors=True)
    os.makedirs(d)
    make(d)
    open(os.path.join(d, "done"), "w").write("")
    return d


# What the peers' build needs from Debian (CoACD's CMake would download them otherwise).
PEER_PACKAGES = ["zlib1g-dev", "libboost-dev", "libboost-iostreams-dev", "libopenvdb-dev", "libtbb-dev", "libspdlog-dev"]


def ensure_packages(packages, why):
    """Installs the Debian packages the benchmark (never the product) needs when they are missing."""
    missing = [p for p in packages if subprocess.run(["dpkg", "-s", p], capture_output=True).returncode != 0]
    if not missing:
        return
    sudo = [] if os.geteuid() == 0 else ["sudo"]
    say("installing %s: %s" % (why, " ".join(missing)))
    env = dict(os.environ, DEBIAN_FRONTEND="noninteractive")
    subprocess.run(sudo + ["apt-get", "update", "-qq"], check=True, env=env)
    subprocess.run(sudo + ["apt-get", "install", "-y", "-qq", "--no-install-recommends"] + missing, check=True, env=env)


def ensure_peers(paths, tools=("coacd", "vhacd")):
    """Builds those of `tools` not built yet (a V-HACD-only benchmark need not wait for CoACD)."""
    missing = [t for t in tools if not os.access(paths.peer(t), os.X_OK)]
    if not missing:
        return
    ensure_packages(PEER_PACKAGES, "the peers' build packages")
    script = os.path.join(paths.peers_src, "build.sh")
    if not os.path.exists(script):
        sys.exit("compare_peers: the peers are not built in %s and no source at %s (set ACD_PEERS_SRC to the folder "
                 "holding CoACD's and V-HACD's archives and build.sh)" % (paths.peers_bin, paths.peers_src))
    say("building %s from %s into %s (once; CoACD takes about 15 min)" % (" and ".join(missing), paths.peers_src,
                                                                          paths.cache))
    subprocess.run([script, os.path.join(paths.cache, "peers-build")] + missing, check=True)


def peer_input(paths, model):
    """The model as an OBJ written by acd's own writer (acd convert), cached by the model's hash."""
    d = cached(paths, key_of("input", fixed_file_hash(model), fixed_file_hash(paths.acd)),
               lambda d: subprocess.run([paths.acd, "convert", model, os.path.join(d, "model.obj")], check=True))
    return os.path.join(d, "model.obj")


def peer_runs():
    """[(label, tool, flags)] in the order they are run: V-HACD (cheap), then CoACD seed by seed, so
    that a cold run stopped early has every threshold once."""
    runs = [("vhacd-%s" % s, "vhacd", f) for s, f in VHACD_SETTINGS]
    for seed in COACD_SEEDS:
        runs += [("coacd-t%g-s%d" % (t, seed), "coacd", ["-t", str(t), "-s", str(seed)]) for t in (0.05, 0.1, 0.02)]
    return runs


def run_peer(paths, obj, tool, flags, existing_only=False):
    binary = os.path.realpath(paths.peer(tool))

    def make(d):
        shutil.copy(obj, os.path.join(d, "model.obj"))
        if tool == "coacd":
            cmd = [binary, "-i", os.path.join(d, "model.obj"), "-o", os.path.join(d, "hulls.obj")] + flags
        else:
            cmd = [binary, "model.obj"] + flags
        rc, sec, mb = timed(cmd, d, os.path.join(d, "log.txt"), PEER_TIMEOUT)
        if tool == "vhacd" and os.path.exists(os.path.join(d, "decomp.obj")):
            os.rename(os.path.join(d, "decomp.obj"), os.path.join(d, "hulls.obj"))
        for extra in glob.glob(os.path.join(d, "decomp.*")) + glob.glob(os.path.join(d, "*.wrl")) + [os.path.join(d, "model.obj")]:
            os.remove(extra)
        json.dump({"command": " ".join([tool, "model.obj"] + (["-o", "hulls.obj"] if tool == "coacd" else []) + flags),
                   "rc": rc, "seconds": sec, "peak_mb": mb}, open(os.path.join(d, "run.json"), "w"))

    return cached(paths, key_of("peer", tool, fixed_file_hash(binary), sha256(obj), *flags), make, existing_only)


def run_acd(paths, model, tau, existing_only=False, flags=()):
    """acd at tau with its defaults, or with `flags` added (part of the cache key)."""
    def make(d):
        cmd = [paths.acd, "decompose", model, "-t", str(tau), "-o", d, "-q", "--threads", "2"] + list(flags)
        rc, sec, mb = timed(cmd, d, os.path.join(d, "log.txt"), PEER_TIMEOUT)
        for c in glob.glob(os.path.join(d, "component_*.off")):
            os.remove(c)
        json.dump({"command": " ".join(["acd decompose MODEL -t %g --threads 2" % tau] + list(flags)), "rc": rc,
                   "seconds": sec, "peak_mb": mb}, open(os.path.join(d, "run.json"), "w"))

    return cached(paths, key_of("acd", fixed_file_hash(paths.acd), fixed_file_hash(model), "%g" % tau, *flags), make,
                  existing_only)


def evaluate(paths, model, hulls, with_acd=True):
    """The evaluators' figures for a hull file: acd-score's score.json and, with_acd, acd evaluate's
    eval.json; cached by model, hulls and the binaries that ran (acd-score alone needs no acd)."""
    evaluators = [("score.json", [paths.score, model, hulls, "--samples", str(SAMPLES)])]
    if with_acd:
        evaluators.insert(0, ("eval.json", [paths.acd, "evaluate", model, hulls, "--json", "--samples", str(SAMPLES),
                                            "--threads", "2"]))

    def make(d):
        for name, cmd in evaluators:
            p = subprocess.run(cmd, capture_output=True, text=True)
            open(os.path.join(d, name), "w").write(p.stdout if p.returncode == 0 else
                                                   json.dumps({"error": p.stderr.strip()[-300:]}))

    binaries = [fixed_file_hash(paths.acd)] if with_acd else ["score only"]
    return cached(paths, key_of("eval", fixed_file_hash(model), sha256(hulls), *binaries, fixed_file_hash(paths.score),
                                str(SAMPLES)), make)


def publish(src, dst, names):
    os.makedirs(dst, exist_ok=True)
    for n in names:
        if os.path.exists(os.path.join(src, n)):
            shutil.copy(os.path.join(src, n), os.path.join(dst, n))


def run(args, paths):
    for tool in ("acd", "score"):
        if not os.access(getattr(paths, tool), os.X_OK):
            sys.exit("compare_peers: %s not found: build it (cmake --build build --target acd_cli acd_score)"
                     % getattr(paths, tool))
    models = models_of(paths, args.set, args.models)
    if args.only in ("acd", "all"):
        for name, model, _ in models:
            for tau in ACD_TAUS:
                say("acd %s tau %g" % (name, tau))
                d = run_acd(paths, model, tau)  # --existing spares the peers only: acd is always this commit's
                dst = os.path.join(paths.out, name, "acd-t%g" % tau)
                publish(d, dst, ["hulls.obj", "report.json", "log.txt", "run.json"])
                if os.path.exists(os.path.join(d, "hulls.obj")):
                    publish(evaluate(paths, model, os.path.join(d, "hulls.obj")), dst, ["eval.json", "score.json"])
    if args.only in ("peers", "all"):
        ensure_peers(paths)
        shard, shards = args.shard
        jobs = [(label, tool, flags, name, model) for label, tool, flags in peer_runs() for name, model, _ in models]
        for label, tool, flags, name, model in jobs[shard::shards]:
            if not args.existing:
                say("%s %s" % (label, name))
            d = run_peer(paths, peer_input(paths, model), tool, flags, args.existing)
            if d is None:
                continue
            dst = os.path.join(paths.out, name, label)
            publish(d, dst, ["hulls.obj", "log.txt", "run.json"])
            if os.path.exists(os.path.join(d, "hulls.obj")):
                publish(evaluate(paths, model, os.path.join(d, "hulls.obj")), dst, ["eval.json", "score.json"])


# ---- the tables -------------------------------------------------------------------------------

def figures(d, evaluator):
    """{parts, iou, excess, seconds, rc} of one published run, by one evaluator; None if absent."""
    try:
        runinfo = json.load(open(os.path.join(d, "run.json")))
        ev = json.load(open(os.path.join(d, "eval.json" if evaluator == "acd" else "score.json")))
    except (OSError, ValueError):
        return None
    if "error" in ev:
        return {"parts": ev.get("hulls"), "iou": None, "excess": None, "seconds": runinfo["seconds"],
                "rc": runinfo["rc"], "peak_mb": runinfo["peak_mb"], "error": ev["error"]}
    return {"parts": ev["hulls"], "iou": ev["iou"], "excess": max(ev["hull_outside_max"], ev["model_to_hulls_max"]),
            "seconds": runinfo["seconds"], "rc": runinfo["rc"], "peak_mb": runinfo["peak_mb"]}


def series_of(out, name, evaluator):
    s = []
    for tau in ACD_TAUS:
        f = figures(os.path.join(out, name, "acd-t%g" % tau), evaluator)
        if f and f["iou"] is not None:
            s.append(dict(f, tau=tau))
    return s


PEER_GROUPS = [("CoACD t=0.1", ["coacd-t0.1-s%d" % s for s in COACD_SEEDS]),
               ("CoACD t=0.05", ["coacd-t0.05-s%d" % s for s in COACD_SEEDS]),
               ("CoACD t=0.02", ["coacd-t0.02-s%d" % s for s in COACD_SEEDS]),
               ("V-HACD default", ["vhacd-default"]), ("V-HACD -h 128", ["vhacd-h128"])]


def compare(out, name, evaluator, figure, labels):
    """Per seed run of one peer setting: (peer parts, peer figure, ratio, kind); None where missing."""
    series = series_of(out, name, evaluator)
    rows = []
    for label in labels:
        f = figures(os.path.join(out, name, label), evaluator)
        if not f or f["iou"] is None or not series:
            continue
        r, kind = fidelity.ratio(series, figure, f["parts"], f[figure])
        rows.append((f["parts"], f[figure], r, kind))
    return rows


def fmt_ratio(r, kind):
    return {"": "%.2f", "<=": "≤ %.2f", "loss": "> %.2f ✗"}[kind] % r


def comparison_table(out, models, evaluator):
    lines = ["| model | peer | runs | peer parts (median, range) | peer IoU | acd / peer at IoU | peer excess | acd / peer at excess |",
             "|---|---|---:|---:|---:|---:|---:|---:|"]
    summary = {}
    for name in models:
        for group, labels in PEER_GROUPS:
            iou = compare(out, name, evaluator, "iou", labels)
            exc = compare(out, name, evaluator, "excess", labels)
            if not iou:
                continue
            parts = [r[0] for r in iou]
            cells = []
            for rows, fig in ((iou, "iou"), (exc, "excess")):
                ratios = [r[2] for r in rows]
                med = fidelity.median(ratios)
                mid = sorted(rows, key=lambda r: r[2])[len(rows) // 2]   # the median run
                spread = " [%.2f–%.2f]" % (min(ratios), max(ratios)) if len(rows) > 1 else ""
                cells += ["%.3f" % mid[1], fmt_ratio(med, mid[3]) + spread]
                summary.setdefault((group, fig), []).append(med)
            prange = " (%d–%d)" % (min(parts), max(parts)) if len(parts) > 1 else ""
            lines.append("| %s | %s | %d | %g%s | %s | %s | %s | %s |" % (name, group, len(parts), fidelity.median(parts), prange,
                                                                     *cells))
    lines += ["", "| peer | n | acd / peer at IoU (geometric mean) | acd fewer at IoU | at excess | acd fewer at excess |",
              "|---|---:|---:|---:|---:|---:|"]
    allr = {"iou": [], "excess": []}
    for group, _ in PEER_GROUPS:
        cells = []
        for fig in ("iou", "excess"):
            xs = summary.get((group, fig), [])
            if group.startswith("CoACD"):
                allr[fig] += xs
            cells += ["%.2f" % fidelity.geomean(xs) if xs else "–", "%d of %d" % (sum(x < 1 for x in xs), len(xs))]
        n = len(summary.get((group, "iou"), []))
        lines.append("| %s | %d | %s |" % (group, n, " | ".join(cells)))
    cells = []
    for fig in ("iou", "excess"):
        xs = allr[fig]
        cells += ["**%.2f**" % fidelity.geomean(xs) if xs else "–", "**%d of %d**" % (sum(x < 1 for x in xs), len(xs))]
    lines.append("| **CoACD, all settings** | %d | %s |" % (len(allr["iou"]), " | ".join(cells)))
    return "\n".join(lines)


def evaluators_table(out, models):
    """Where the two evaluators differ by more than their sampling error."""
    lines = ["| run | IoU: acd evaluate | acd-score | difference / error | excess: acd evaluate | acd-score |",
             "|---|---:|---:|---:|---:|---:|"]
    diffs = []
    for name in models:
        for d in sorted(glob.glob(os.path.join(out, name, "*"))):
            a, b = figures(d, "acd"), figures(d, "score")
            if not a or not b or a["iou"] is None or b["iou"] is None:
                continue
            ea = json.load(open(os.path.join(d, "eval.json")))["iou_stderr"]
            eb = json.load(open(os.path.join(d, "score.json")))["iou_stderr"]
            z = abs(a["iou"] - b["iou"]) / max(1e-12, (ea * ea + eb * eb) ** 0.5)
            diffs.append((z, "%s/%s" % (name, os.path.basename(d)), a, b))
    diffs.sort(key=lambda x: -x[0])
    for z, label, a, b in diffs[:12]:
        lines.append("| %s | %.4f | %.4f | %.1f | %.4f | %.4f |" % (label, a["iou"], b["iou"], z, a["excess"], b["excess"]))
    within = sum(z <= 3 for z, *_ in diffs)
    lines.append("")
    lines.append("%d of %d runs agree on IoU within 3 standard errors; the table lists the largest differences."
                 % (within, len(diffs)))
    return "\n".join(lines)


def table(args, paths):
    models = [m[0] for m in models_of(paths, args.set, args.models)]
    print("#### At equal fidelity, scored by `acd evaluate`\n")
    print(comparison_table(paths.out, models, "acd"))
    print("\n#### The same, scored by `acd-score` (CGAL only, no libacd code)\n")
    print(comparison_table(paths.out, models, "score"))
    print("\n#### The two evaluators side by side\n")
    print(evaluators_table(paths.out, models))
    # Each run's wall time and peak memory are in its run.json; they are not tabled here, since
    # the peers' runs may be cached from a run that shared the machine (bench/run_corpus.sh times acd).


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("mode", choices=["run", "table"])
    ap.add_argument("--set", choices=["corpus", "heldout", "all"], default="all")
    ap.add_argument("--models", type=lambda s: s.split(","), default=None)
    ap.add_argument("--only", choices=["acd", "peers", "all"], default="all")
    ap.add_argument("--out", default=os.path.join(ROOT, "out/compare_peers"))
    ap.add_argument("--existing", action="store_true",
                    help="publish and score only the peer runs already in the cache, start none (acd always runs)")
    ap.add_argument("--shard", type=lambda s: tuple(int(x) for x in s.split("/")), default=(0, 1),
                    help="I/N: run only every N-th peer run from the I-th (several processes share a cold run)")
    args = ap.parse_args()
    paths = Paths(args.out)
    (run if args.mode == "run" else table)(args, paths)


if __name__ == "__main__":
    main()

#!/usr/bin/python3
"""Helper of bench/invariance.sh: rigid motions of OFF models and the comparison of the results.

  invariance.py move IN.off OUT.off MOTION   MOTION: random:SEED | tiny | turn
      writes OUT.off (every vertex moved; faces and any colours copied) and OUT.json (R, t)
  invariance.py table RESULTS TAU... -- MODEL...
      compares RESULTS/MODEL/tTAU/MOTION/ with RESULTS/MODEL/tTAU/orig/ and prints a Markdown
      table; exit 1 when a model has fewer than 9 of its motions matching.

Motions: random:SEED is a rotation by a uniformly random unit quaternion (Shoemake's method,
Python's random seeded with SEED) and a translation by up to one bounding-box diagonal per
axis; tiny translates every coordinate by 1e-9 x the bounding-box diagonal; turn is the exact
90-degree turn (x, y, z) -> (-y, x, z), which leaves every coordinate exactly representable.

A motion matches when the part count is the same and every component of the moved run has a
counterpart in the original run: its centroid, mapped back through the inverse motion, is
nearest to that counterpart's centroid (one to one, within 1e-6 x the diagonal), and their
volumes (report.json components[].volume, normalised units) agree within 1e-6 relative.
Centroids are computed here from the component_NNN.off files (volume-weighted).
"""
import json
import math
import os
import random
import sys

VOLUME_TOL = 1e-6
CENTROID_TOL = 1e-6   # x the bounding-box diagonal
MOTIONS = ["random:%d" % s for s in range(1, 9)] + ["tiny", "turn"]


def data_lines(lines):
    """Indices of lines that carry data (not blank, not a comment)."""
    return [i for i, l in enumerate(lines) if l.split("#", 1)[0].strip()]


def read_off(path):
    """(lines, index of each vertex line, vertices, triangles or None when not asked)."""
    lines = open(path).read().split("\n")
    idx = data_lines(lines)
    head = lines[idx[0]].split("#", 1)[0].split()
    if not head[0].endswith("OFF"):
        sys.exit("invariance.py: %s is not an OFF file" % path)
    if len(head) > 1:                       # counts on the header line
        counts, first = head[1:], 1
    else:
        counts, first = lines[idx[1]].split(), 2
    nv, nf = int(counts[0]), int(counts[1])
    vidx = idx[first:first + nv]
    verts = [tuple(float(x) for x in lines[i].split()[:3]) for i in vidx]
    fidx = idx[first + nv:first + nv + nf]
    return lines, vidx, verts, fidx


def diagonal(verts):
    lo = [min(v[k] for v in verts) for k in range(3)]
    hi = [max(v[k] for v in verts) for k in range(3)]
    return math.sqrt(sum((h - l) ** 2 for h, l in zip(hi, lo)))


def motion(name, diag):
    """(R as 3 rows, t) of the named motion."""
    if name == "tiny":
        return [[1, 0, 0], [0, 1, 0], [0, 0, 1]], [1e-9 * diag] * 3
    if name == "turn":
        return [[0, -1, 0], [1, 0, 0], [0, 0, 1]], [0.0, 0.0, 0.0]
    rng = random.Random(int(name.split(":")[1]))
    u1, u2, u3 = rng.random(), rng.random(), rng.random()
    a, b = math.sqrt(1 - u1), math.sqrt(u1)
    w, x, y, z = a * math.sin(2 * math.pi * u2), a * math.cos(2 * math.pi * u2), \
        b * math.sin(2 * math.pi * u3), b * math.cos(2 * math.pi * u3)
    R = [[1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)],
         [2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)],
         [2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)]]
    return R, [rng.uniform(-1, 1) * diag for _ in range(3)]


def apply(R, t, p):
    return tuple(sum(R[r][c] * p[c] for c in range(3)) + t[r] for r in range(3))


def unapply(R, t, p):
    q = [p[k] - t[k] for k in range(3)]
    return tuple(sum(R[r][c] * q[r] for r in range(3)) for c in range(3))


def move(src, dst, name):
    lines, vidx, verts, _ = read_off(src)
    R, t = motion(name, diagonal(verts))
    for i, v in zip(vidx, verts):
        rest = lines[i].split()[3:]        # colours etc. stay as they were
        lines[i] = " ".join([repr(c) for c in apply(R, t, v)] + rest)
    open(dst, "w").write("\n".join(lines))
    json.dump({"motion": name, "R": R, "t": t, "diagonal": diagonal(verts)},
              open(os.path.splitext(dst)[0] + ".json", "w"))


def centroid(path):
    lines, _, verts, fidx = read_off(path)
    vol, c = 0.0, [0.0, 0.0, 0.0]
    for i in fidx:
        f = [int(x) for x in lines[i].split()[1:4]]
        a, b, d = verts[f[0]], verts[f[1]], verts[f[2]]
        v6 = (a[0] * (b[1] * d[2] - b[2] * d[1]) - a[1] * (b[0] * d[2] - b[2] * d[0])
              + a[2] * (b[0] * d[1] - b[1] * d[0]))
        vol += v6
        for k in range(3):
            c[k] += v6 * (a[k] + b[k] + d[k]) / 4
    return tuple(x / vol for x in c) if vol else tuple(verts[0])


def load_run(d):
    """(rc, volumes, centroids) of one run, or None when it did not finish."""
    try:
        rc = int(open(os.path.join(d, "rc")).read())
        rep = json.load(open(os.path.join(d, "report.json")))
    except (OSError, ValueError):
        return None
    vols = [c["volume"] for c in rep["components"]]
    cents = [centroid(os.path.join(d, "component_%03d.off" % i)) for i in range(len(vols))]
    return rc, vols, cents


def compare(orig, moved, m):
    """(matches, max relative volume difference or None)."""
    if len(orig[1]) != len(moved[1]):
        return False, None
    tol = CENTROID_TOL * m["diagonal"]
    used, worst, ok = set(), 0.0, True
    for v, c in zip(moved[1], moved[2]):
        back = unapply(m["R"], m["t"], c)
        j = min(range(len(orig[2])), key=lambda k: math.dist(back, orig[2][k]))
        ok &= j not in used and math.dist(back, orig[2][j]) <= tol
        used.add(j)
        worst = max(worst, abs(v - orig[1][j]) / abs(orig[1][j]))
    return ok and worst <= VOLUME_TOL, worst


def table(results, taus, models, meshes):
    print("| model | τ | motions matching | 1e-9 shift, 90° turn | max rel. volume diff | part counts (original; moved) | unresolved runs |")
    print("|---|---:|---:|:---:|---:|---|---:|")
    bad = []
    for model in models:
        for tau in taus:
            base = os.path.join(results, model, "t" + tau)
            orig = load_run(os.path.join(base, "orig"))
            if orig is None:
                print("| %s | %s | no original run | | | | |" % (model, tau)); bad.append(model); continue
            n, worst, counts, unresolved, exact = 0, None, {}, int(orig[0] == 4), {}
            for name in MOTIONS:
                tag = name.replace(":", "")
                run = load_run(os.path.join(base, tag))
                if run is None:
                    continue
                m = json.load(open(os.path.join(meshes, "%s-%s.json" % (model, tag))))
                ok, w = compare(orig, run, m)
                n += ok
                exact[name] = "yes" if ok else "no"
                unresolved += run[0] == 4
                if w is not None:
                    worst = w if worst is None else max(worst, w)
                counts[len(run[1])] = counts.get(len(run[1]), 0) + 1
            seen = ", ".join("%d×%d" % (k, v) if v > 1 else str(k) for k, v in sorted(counts.items()))
            print("| %s | %s | %d of %d | %s, %s | %s | %d; %s | %d |" % (
                model, tau, n, len(MOTIONS), exact.get("tiny", "–"), exact.get("turn", "–"),
                "–" if worst is None else "%.1e" % worst,
                len(orig[1]), seen, unresolved))
            if n < len(MOTIONS) - 1:
                bad.append(model)
    if bad:
        print("\nFewer than %d of %d motions match: %s" % (len(MOTIONS) - 1, len(MOTIONS), ", ".join(sorted(set(bad)))))
    return 1 if bad else 0


if __name__ == "__main__":
    if sys.argv[1] == "move":
        move(sys.argv[2], sys.argv[3], sys.argv[4])
    elif sys.argv[1] == "motions":
        print(" ".join(MOTIONS))
    elif sys.argv[1] == "table":
        args = sys.argv[2:]
        sep = args.index("--")
        results, taus, models = args[0], args[1:sep], args[sep + 1:]
        sys.exit(table(results, taus, models, os.path.join(results, "meshes")))
    else:
        sys.exit(__doc__)

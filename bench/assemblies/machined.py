#!/usr/bin/python3
"""Generates single machined parts as CAD systems export them: plates with filleted pockets, risers
with bores and counterbores, brackets with slots, ribbed housings — modelled in OpenSCAD, then
every planar face triangulated again by ear clipping, the way CAD exporters write STL: a face
with holes becomes a fan of long thin triangles reaching across it, not OpenSCAD's tidy
triangulation. Those slivers are what cuts through exported parts meet.

    bench/assemblies/machined.py OUT_DIR [--count N] [--seed S]

Writes OUT_DIR/NAME.stl and OUT_DIR/manifest.tsv (name, kind, faces). The same count and seed
give the same files. Needs Debian's openscad and python3-mapbox-earcut.
"""
import argparse
import os
import random
import shutil
import sys
import tempfile

import numpy as np
try:
    import mapbox_earcut
except ImportError:
    sys.exit("machined.py: mapbox_earcut not found (apt-get install python3-mapbox-earcut)")

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from generate import export_part, write_stl  # noqa: E402


# ---------------------------------------------------------------- the kinds of part (millimetres)

def rounded_polygon(sides, radius, fillet):
    """A regular polygon with rounded corners, as OpenSCAD 2D."""
    return "offset(r=%g) circle(r=%g, $fn=%d);" % (fillet, max(radius - fillet, 0.5), sides)


def pocketed_plate(r):
    w, d, t = r.uniform(60, 120), r.uniform(50, 100), r.uniform(8, 20)
    sides = r.choice([4, 6, 8, 8, 12])
    radius = min(w, d) * r.uniform(0.25, 0.38)
    depth = t * r.uniform(0.4, 0.8)
    cut = "translate([%g,%g,%g]) linear_extrude(%g) %s" % (
        w / 2, d / 2, t - depth, depth + 1, rounded_polygon(sides, radius, r.uniform(1, 4)))
    holes = " ".join("translate([%g,%g,-1]) cylinder(r=%g,h=%g);" % (x, y, r.choice([1.6, 2.25, 2.75]), t + 2)
                     for x in (5, w - 5) for y in (5, d - 5))
    return "difference(){cube([%g,%g,%g]); %s %s}" % (w, d, t, cut, holes)


def riser(r):
    w, d, h = r.uniform(30, 60), r.uniform(20, 40), r.uniform(30, 80)
    bore = min(w, d) * r.uniform(0.2, 0.35)
    cbore = bore * r.uniform(1.3, 1.6)
    feet = "translate([%g,0,0]) cube([%g,%g,%g]);" % (-w * 0.4, w * 1.8, d, h * 0.15)
    body = "union(){cube([%g,%g,%g]); %s}" % (w, d, h, feet)
    cuts = ("translate([%g,-1,%g]) rotate([-90,0,0]) cylinder(r=%g,h=%g);" % (w / 2, h * 0.65, bore, d + 2) +
            "translate([%g,-1,%g]) rotate([-90,0,0]) cylinder(r=%g,h=%g);" % (w / 2, h * 0.65, cbore, d * 0.3 + 1) +
            " ".join("translate([%g,%g,-1]) cylinder(r=2.25,h=%g);" % (x, d / 2, h * 0.15 + 2)
                     for x in (-w * 0.25, w * 1.25)))
    return "difference(){%s %s}" % (body, cuts)


def slotted_bracket(r):
    a, b, t, d = r.uniform(40, 80), r.uniform(30, 60), r.uniform(4, 8), r.uniform(25, 50)
    body = "union(){cube([%g,%g,%g]); cube([%g,%g,%g]);}" % (a, d, t, t, d, b)
    slots = []
    for k in range(r.randint(1, 3)):
        y = d * (k + 1) / (r.randint(1, 3) + 2)
        slots.append("translate([0,%g,-1]) linear_extrude(%g) hull(){translate([%g,0]) circle(r=2.5,$fn=24);"
                     "translate([%g,0]) circle(r=2.5,$fn=24);}" % (y, t + 2, a * 0.35, a * 0.8))
    gusset = "translate([0,%g,0]) rotate([90,0,0]) linear_extrude(%g) polygon([[0,0],[%g,0],[0,%g]]);" % (
        d / 2 + t / 2, t, a * 0.5, b * 0.5)
    return "difference(){union(){%s %s} %s}" % (body, gusset, " ".join(slots))


def ribbed_housing(r):
    w, d, h, wall = r.uniform(50, 100), r.uniform(40, 80), r.uniform(20, 40), r.uniform(2, 4)
    shell = "difference(){cube([%g,%g,%g]); translate([%g,%g,%g]) cube([%g,%g,%g]);}" % (
        w, d, h, wall, wall, wall, w - 2 * wall, d - 2 * wall, h)
    ribs = " ".join("translate([%g,%g,0]) cube([%g,%g,%g]);" % (w * (i + 1) / 4 - wall / 2, 0, wall, d, h * 0.6)
                    for i in range(3))
    # Bosses sink 1 mm into the walls (as a CAD fillet joins them): a boss tangent to a wall
    # exports as a surface touching itself along a line.
    bosses = " ".join("translate([%g,%g,0]) difference(){cylinder(r=4,h=%g); cylinder(r=1.6,h=%g);}" % (
        x, y, h * 0.8, h) for x in (wall + 3, w - wall - 3) for y in (wall + 3, d - wall - 3))
    return "union(){%s %s %s}" % (shell, ribs, bosses)


def flanged_hub(r):
    rf, tf = r.uniform(25, 45), r.uniform(5, 10)
    rh, hh = rf * r.uniform(0.35, 0.5), r.uniform(15, 35)
    bore = rh * r.uniform(0.4, 0.6)
    n = r.choice([3, 4, 6])
    holes = " ".join("rotate([0,0,%g]) translate([%g,0,-1]) cylinder(r=%g,h=%g);" % (
        360 * i / n, (rf + rh) / 2, r.uniform(2, 3.5), tf + 2) for i in range(n))
    key = "translate([%g,%g,-1]) cube([%g,%g,%g]);" % (bore - 1, -2, 3, 4, tf + hh + 2)
    return "difference(){union(){cylinder(r=%g,h=%g); cylinder(r=%g,h=%g);} translate([0,0,-1]) " \
           "cylinder(r=%g,h=%g); %s %s}" % (rf, tf, rh, tf + hh, bore, tf + hh + 2, holes, key)


KINDS = [pocketed_plate, riser, slotted_bracket, ribbed_housing, flanged_hub]


# ---------------------------------------------------------------- the exporter's triangulation

def planar_regions(faces, points):
    """Faces grouped into edge-connected regions that lie in one plane (normals within 1e-9)."""
    normals = []
    for a, b, c in faces:
        n = np.cross(points[b] - points[a], points[c] - points[a])
        length = np.linalg.norm(n)
        normals.append(n / length if length > 0 else n)
    by_edge = {}
    for f, (a, b, c) in enumerate(faces):
        for u, v in ((a, b), (b, c), (c, a)):
            by_edge.setdefault((min(u, v), max(u, v)), []).append(f)
    region = [-1] * len(faces)
    regions = []
    for start in range(len(faces)):
        if region[start] >= 0:
            continue
        region[start] = len(regions)
        members, stack = [start], [start]
        while stack:
            f = stack.pop()
            a, b, c = faces[f]
            for u, v in ((a, b), (b, c), (c, a)):
                for g in by_edge[(min(u, v), max(u, v))]:
                    if region[g] < 0 and np.dot(normals[g], normals[start]) > 1 - 1e-9 and \
                            abs(np.dot(points[faces[g][0]] - points[faces[start][0]], normals[start])) < 1e-6:
                        region[g] = len(regions)
                        members.append(g)
                        stack.append(g)
        regions.append((members, normals[start]))
    return regions


def boundary_loops(faces, members):
    """The region's boundary as closed vertex loops (None if it is not a set of simple loops)."""
    directed = set()
    for f in members:
        a, b, c = faces[f]
        directed.update(((a, b), (b, c), (c, a)))
    nxt = {}
    for u, v in directed:
        if (v, u) not in directed:
            if u in nxt:
                return None  # a vertex where two loops touch
            nxt[u] = v
    loops = []
    while nxt:
        start = next(iter(nxt))
        loop, v = [start], nxt.pop(start)
        while v != start:
            if v not in nxt:
                return None
            loop.append(v)
            v = nxt.pop(v)
        loops.append(loop)
    return loops


def ear_clipped(tris):
    """The same surface with every planar face of two or more triangles triangulated by ear clipping."""
    key, points, faces = {}, [], []
    for t in tris:
        face = []
        for v in t:
            if v not in key:
                key[v] = len(points)
                points.append(np.array(v, dtype=float))
            face.append(key[v])
        if len(set(face)) == 3:
            faces.append(tuple(face))
    out = []
    for members, normal in planar_regions(faces, points):
        loops = boundary_loops(faces, members) if len(members) > 1 else None
        if loops:
            axis = int(np.argmax(np.abs(normal)))
            u, v = [(1, 2), (2, 0), (0, 1)][axis]
            areas = []
            for loop in loops:
                xy = np.array([[points[i][u], points[i][v]] for i in loop])
                areas.append(0.5 * np.sum(xy[:, 0] * np.roll(xy[:, 1], -1) - np.roll(xy[:, 0], -1) * xy[:, 1]))
            outer = int(np.argmax(np.abs(areas)))
            order = [outer] + [k for k in range(len(loops)) if k != outer]
            ring = [i for k in order for i in loops[k]]
            ends = np.cumsum([len(loops[k]) for k in order]).astype(np.uint32)
            xy = np.array([[points[i][u], points[i][v]] for i in ring], dtype=np.float64)
            idx = mapbox_earcut.triangulate_float64(xy, ends).reshape(-1, 3)
            if len(idx) == len(ring) + 2 * (len(loops) - 1) - 2:  # a complete triangulation
                for a, b, c in idx:
                    p, q, s = points[ring[a]], points[ring[b]], points[ring[c]]
                    if np.dot(np.cross(q - p, s - p), normal) < 0:
                        q, s = s, q
                    out.append((tuple(p), tuple(q), tuple(s)))
                continue
        out.extend(tuple(tuple(points[i]) for i in faces[f]) for f in members)
    return out


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("out")
    ap.add_argument("--count", type=int, default=20)
    ap.add_argument("--seed", type=int, default=1)
    args = ap.parse_args()
    if not shutil.which("openscad"):
        sys.exit("machined.py: openscad not found (apt-get install openscad)")
    os.makedirs(args.out, exist_ok=True)
    manifest = ["name\tkind\tfaces"]
    for i in range(args.count):
        r = random.Random(args.seed * 100019 + i)
        kind = KINDS[i % len(KINDS)]
        with tempfile.TemporaryDirectory() as work:
            tris = ear_clipped(export_part(kind(r), work, 0, preamble="$fn=48;\n"))
        name = "%02d_%s" % (i, kind.__name__)
        write_stl(os.path.join(args.out, name + ".stl"), tris)
        manifest.append("%s\t%s\t%d" % (name, kind.__name__, len(tris)))
        print("machined.py: %s (%d faces)" % (name, len(tris)), file=sys.stderr)
    with open(os.path.join(args.out, "manifest.tsv"), "w") as f:
        f.write("\n".join(manifest) + "\n")


if __name__ == "__main__":
    main()

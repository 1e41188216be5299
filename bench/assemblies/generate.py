#!/usr/bin/python3
"""Generates CAD assemblies the way exporters write them: each part modelled in OpenSCAD with the
MCAD library (bolts, nuts, washers, gears, bearings, stepper motors, servos), exported on its own,
and the parts' triangles concatenated into one file, so that the shells touch, overlap and nest
as in a real export (a bolt's shank inside its plate, a motor flush against its bracket, a
bearing in its bore). Some files get the defects exporters add: a shell repeated, a shell
flipped inside out, a cap left open, faces inside a part.

    bench/assemblies/generate.py OUT_DIR [--count N] [--seed S]

Writes OUT_DIR/NAME.stl (or .obj) and OUT_DIR/manifest.tsv (name, kind, parts, defects). The
same count and seed give the same files (OpenSCAD writes its triangles in varying order; they are sorted). Needs Debian's
openscad and openscad-mcad.
"""
import argparse
import math
import os
import random
import shutil
import struct
import subprocess
import sys
import tempfile

MCAD = "use <MCAD/metric_fastners.scad>\nuse <MCAD/involute_gears.scad>\nuse <MCAD/bearing.scad>\n" \
       "include <MCAD/stepper.scad>\nuse <MCAD/servos.scad>\n$fn=32;\n"


def place(body, at=(0, 0, 0), rot=(0, 0, 0)):
    return "translate([%g,%g,%g]) rotate([%g,%g,%g]) %s" % (*at, *rot, body)


# ---------------------------------------------------------------- the kinds of assembly
# Each returns a list of OpenSCAD part bodies (one shell or a few each), in millimetres.

def plate_with_bolts(r):
    w, d, t = r.uniform(40, 90), r.uniform(30, 70), r.uniform(3, 8)
    dia = r.choice([3, 4, 5])
    holes = r.random() < 0.5  # bolts in holes (touching their walls) or simply through the plate
    nx, ny = r.randint(2, 5), r.randint(2, 4)
    spots = [(w * (i + 0.5) / nx, d * (j + 0.5) / ny) for i in range(nx) for j in range(ny)]
    plate = "cube([%g,%g,%g]);" % (w, d, t)
    if holes:
        plate = "difference(){%s %s}" % (plate, " ".join(
            "translate([%g,%g,-1]) cylinder(r=%g,h=%g);" % (x, y, dia / 2, t + 2) for x, y in spots))
    parts = [plate]
    length = t + r.choice([0, dia, 2 * dia])
    for x, y in spots:
        # cap_bolt's head is below z=0 and its shank above: turned over, the head rests on the plate.
        parts.append(place("cap_bolt(%g,%g);" % (dia, length), (x, y, t), (180, 0, 0)))
        if r.random() < 0.4:
            parts.append(place("washer(%g);" % dia, (x, y, -0.1 * dia)))
    return parts


def motor_mount(r):
    t = r.uniform(3, 6)
    size = 50
    bracket = ["cube([%g,%g,%g]);" % (size, size, t),                # foot
               "translate([0,0,0]) cube([%g,%g,%g]);" % (t, size, size)]  # upright: overlaps the foot
    motor = place("motor(Nema17, NemaMedium);", (t, size / 2, size / 2 + t / 2), (0, -90, 0))
    screws = [place("cap_bolt(3,%g);" % (t + 6), (0, size / 2 + dy, size / 2 + t / 2 + dz), (0, 90, 0))
              for dy in (-15.5, 15.5) for dz in (-15.5, 15.5)]
    ribs = [] if r.random() < 0.4 else [
        "translate([%g,%g,%g]) rotate([90,0,0]) linear_extrude(%g) polygon([[0,0],[%g,0],[0,%g]]);"
        % (t, y + 2, t, 2, r.uniform(15, 30), r.uniform(15, 30)) for y in (2, size - 4)]
    return bracket + [motor] + screws + ribs


def gear_pair(r):
    pitch = r.uniform(200, 320)
    teeth = (r.randint(12, 20), r.randint(20, 32))
    radius = [n * pitch / 360.0 for n in teeth]  # pitch radius = teeth * circular pitch / (2 pi), in MCAD units
    gap = radius[0] + radius[1]
    base = "cube([%g,%g,4]);" % (gap + radius[0] + radius[1] + 20, 2 * max(radius) + 20)
    parts = [base]
    x = [radius[0] + 10, radius[0] + 10 + gap]
    for i in (0, 1):
        parts.append(place("gear(number_of_teeth=%d, circular_pitch=%g, gear_thickness=6, rim_thickness=6, "
                           "hub_thickness=10, bore_diameter=5);" % (teeth[i], pitch),
                           (x[i], max(radius) + 10, 8)))
        parts.append(place("cylinder(r=3,h=24);", (x[i], max(radius) + 10, 2)))  # the shaft, into base and bore
        parts.append(place("cylinder(r=5,h=4);", (x[i], max(radius) + 10, 4)))   # spacer on the base
    return parts


def bearing_block(r):
    model = r.choice([608, 624, 688])
    outer = {608: 22, 624: 13, 688: 16}[model]
    width = {608: 7, 624: 5, 688: 5}[model]
    side = outer + r.uniform(10, 20)
    block = "difference(){cube([%g,%g,%g]); translate([%g,%g,-1]) cylinder(r=%g,h=%g);}" % (
        side, side, width + 4, side / 2, side / 2, outer / 2, width + 6)
    parts = [block, place("bearing(model=%d);" % model, (side / 2, side / 2, 2))]
    parts.append(place("cylinder(r=%g,h=%g);" % (outer / 8, width + 30), (side / 2, side / 2, -10)))
    parts += [place("cap_bolt(3,10);", (x, y, width + 4), (180, 0, 0)) for x in (3, side - 3) for y in (3, side - 3)]
    return parts


def servo_bracket(r):
    t = r.uniform(2, 4)
    plate = "cube([60,40,%g]);" % t
    servo = place("alignds420(screws=1);", (30, 20, t))
    horn = place("cylinder(r=8,h=2);", (30 + 0, 20 - 0, t + 19 + r.uniform(0, 1)))
    return [plate, servo, horn] + [place("cap_bolt(2,8);", (x, 35, t), (180, 0, 0)) for x in (8, 52)]


def enclosure(r):
    w, d, h, wall = r.uniform(40, 80), r.uniform(30, 60), r.uniform(15, 30), 2
    box = "difference(){cube([%g,%g,%g]); translate([%g,%g,%g]) cube([%g,%g,%g]);}" % (
        w, d, h, wall, wall, wall, w - 2 * wall, d - 2 * wall, h)
    lid = place("cube([%g,%g,%g]);" % (w, d, wall), (0, 0, h))
    parts = [box, lid]
    standoffs = [(wall + 4, wall + 4), (w - wall - 4, wall + 4), (wall + 4, d - wall - 4), (w - wall - 4, d - wall - 4)]
    for x, y in standoffs:
        parts.append(place("cylinder(r=2.5,h=5);", (x, y, wall)))                     # on the floor
        parts.append(place("cap_bolt(2,%g);" % (wall + 4), (x, y, h + wall), (180, 0, 0)))  # through the lid
    parts.append(place("cube([%g,%g,1.6]);" % (w - 2 * wall - 4, d - 2 * wall - 4), (wall + 2, wall + 2, wall + 5)))  # PCB on them
    parts.append(place("cube([8,6,4]);", (wall + 10, wall + 10, wall + 6.6)))  # a chip on the PCB
    return parts


KINDS = [plate_with_bolts, motor_mount, gear_pair, bearing_block, servo_bracket, enclosure]

# ---------------------------------------------------------------- triangles


def read_stl(path):
    """Triangles of an ASCII or binary STL (what OpenSCAD writes)."""
    data = open(path, "rb").read()
    if data[:5] == b"solid" and b"facet" in data[:300]:
        tris, cur = [], []
        for line in data.decode().splitlines():
            words = line.split()
            if words and words[0] == "vertex":
                cur.append(tuple(float(v) for v in words[1:4]))
                if len(cur) == 3:
                    tris.append(tuple(cur))
                    cur = []
        return tris
    n = struct.unpack("<I", data[80:84])[0]
    return [tuple(struct.unpack("<3f", data[84 + 50 * i + 12 + 12 * k:84 + 50 * i + 24 + 12 * k]) for k in range(3))
            for i in range(n)]


def canonical_order(tris):
    """The triangles sorted, each starting at its smallest corner: OpenSCAD writes the same
    triangles in a different order from run to run, and the files should not change."""
    turned = []
    for t in tris:
        k = min(range(3), key=lambda i: t[i])
        turned.append(tuple(t[k:]) + tuple(t[:k]))
    return sorted(turned)


def write_stl(path, tris):
    with open(path, "wb") as f:
        f.write(b"acd generated assembly".ljust(80, b" "))
        f.write(struct.pack("<I", len(tris)))
        for t in tris:
            f.write(struct.pack("<3f", 0, 0, 0))
            for v in t:
                f.write(struct.pack("<3f", *v))
            f.write(b"\0\0")


def write_obj(path, parts):
    """One `o` object per part, each with its own vertices (as exporters write them)."""
    with open(path, "w") as f:
        base = 1
        for k, tris in enumerate(parts):
            f.write("o part%d\n" % k)
            for t in tris:
                for v in t:
                    f.write("v %.9g %.9g %.9g\n" % v)
            for i in range(len(tris)):
                f.write("f %d %d %d\n" % (base + 3 * i, base + 3 * i + 1, base + 3 * i + 2))
            base += 3 * len(tris)


def add_defect(r, parts, kind):
    """Exporters' defects, on a random part: a repeated shell, a flipped one, an open cap, an inner wall."""
    k = r.randrange(len(parts))
    if kind == "duplicate":
        parts.append(list(parts[k]))
    elif kind == "flipped":
        parts[k] = [(t[0], t[2], t[1]) for t in parts[k]]
    elif kind == "open_cap":
        # drop the faces whose normal points up most and that lie at the part's top
        top = max(v[2] for t in parts[k] for v in t)
        parts[k] = [t for t in parts[k] if not all(abs(v[2] - top) < 1e-6 for v in t)] or parts[k]
    elif kind == "inner_faces":
        xs = [v for t in parts[k] for v in t]
        lo = [min(p[i] for p in xs) for i in range(3)]
        hi = [max(p[i] for p in xs) for i in range(3)]
        mid = [(a + b) / 2 for a, b in zip(lo, hi)]
        a = (lo[0] * 0.75 + hi[0] * 0.25, mid[1], lo[2] * 0.75 + hi[2] * 0.25)
        b = (lo[0] * 0.25 + hi[0] * 0.75, mid[1], lo[2] * 0.75 + hi[2] * 0.25)
        c = (lo[0] * 0.25 + hi[0] * 0.75, mid[1], lo[2] * 0.25 + hi[2] * 0.75)
        d = (lo[0] * 0.75 + hi[0] * 0.25, mid[1], lo[2] * 0.25 + hi[2] * 0.75)
        parts[k] = parts[k] + [(a, b, c), (a, c, d)]


def export_part(body, work, index, preamble=MCAD):
    """One part's triangles as OpenSCAD exports `preamble` + `body`, in canonical order."""
    scad = os.path.join(work, "part%d.scad" % index)
    stl = os.path.join(work, "part%d.stl" % index)
    with open(scad, "w") as f:
        f.write(preamble + body + "\n")
    run = subprocess.run(["openscad", "-o", stl, scad], capture_output=True, text=True)
    if run.returncode != 0 or not os.path.exists(stl):
        sys.exit("%s: openscad failed on %s:\n%s" % (os.path.basename(sys.argv[0]), body, run.stderr[-2000:]))
    return canonical_order(read_stl(stl))


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("out")
    ap.add_argument("--count", type=int, default=36)
    ap.add_argument("--seed", type=int, default=1)
    args = ap.parse_args()
    if not shutil.which("openscad"):
        sys.exit("generate.py: openscad not found (apt-get install openscad openscad-mcad)")
    os.makedirs(args.out, exist_ok=True)
    manifest = ["name\tkind\tparts\tdefects"]
    for i in range(args.count):
        r = random.Random(args.seed * 100003 + i)
        kind = KINDS[i % len(KINDS)]
        bodies = kind(r)
        with tempfile.TemporaryDirectory() as work:
            parts = [export_part(b, work, k) for k, b in enumerate(bodies)]
        defects = []
        if i % 3 == 2:  # a third of the files carry an exporter's defect
            defect = ["duplicate", "flipped", "open_cap", "inner_faces"][(i // 3) % 4]
            add_defect(r, parts, defect)
            defects.append(defect)
        name = "%02d_%s" % (i, kind.__name__)
        if i % 4 == 3:
            write_obj(os.path.join(args.out, name + ".obj"), parts)
        else:
            write_stl(os.path.join(args.out, name + ".stl"), [t for p in parts for t in p])
        manifest.append("%s\t%s\t%d\t%s" % (name, kind.__name__, len(parts), ",".join(defects) or "-"))
        print("generate.py: %s (%d parts%s)" % (name, len(parts), ", " + defects[0] if defects else ""),
              file=sys.stderr)
    with open(os.path.join(args.out, "manifest.tsv"), "w") as f:
        f.write("\n".join(manifest) + "\n")


if __name__ == "__main__":
    main()

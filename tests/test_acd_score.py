#!/usr/bin/python3
"""Tests of the second evaluator, acd-score (bench/score/score.cpp), on files made here with known
answers. Run by ctest with the executable's path: test_acd_score.py BUILD/bin/acd-score"""
import json
import os
import subprocess
import sys
import tempfile
import unittest

SCORE = None

# The unit cube's six faces as quads (outward), corners 0..7 at (x, y, z) = bits of the index.
CORNERS = [(x, y, z) for z in (0, 1) for y in (0, 1) for x in (0, 1)]
QUADS = [(0, 2, 3, 1), (4, 5, 7, 6), (0, 1, 5, 4), (2, 6, 7, 3), (0, 4, 6, 2), (1, 3, 7, 5)]


def write_off(path, vertices, faces):
    with open(path, "w") as f:
        f.write("OFF\n%d %d 0\n" % (len(vertices), len(faces)))
        for v in vertices:
            f.write("%.17g %.17g %.17g\n" % v)
        for face in faces:
            f.write("%d %s\n" % (len(face), " ".join(map(str, face))))


def write_hulls(path, boxes):
    """Each box (lo, hi) as one OBJ object of its eight corners (acd-score rebuilds the hull)."""
    with open(path, "w") as f:
        base = 1
        for i, (lo, hi) in enumerate(boxes):
            f.write("o hull_%d\n" % i)
            for x, y, z in CORNERS:
                f.write("v %g %g %g\n" % (hi[0] if x else lo[0], hi[1] if y else lo[1], hi[2] if z else lo[2]))
            for q in QUADS:
                f.write("f %s\n" % " ".join(str(base + k) for k in q))
            base += 8


def score(model, hulls):
    out = subprocess.run([SCORE, model, hulls, "--samples", "20000", "--surface-samples", "20000"],
                         check=True, capture_output=True, text=True).stdout
    return json.loads(out)


class OpenShells(unittest.TestCase):
    """Hulls that fill the unit cube exactly stand off it by nothing, however its surface is split."""

    def two_halves(self, tmp):
        hulls = os.path.join(tmp, "halves.obj")  # the cube cut at x = 1/2: a hull face through its middle
        write_hulls(hulls, [((0, 0, 0), (0.5, 1, 1)), ((0.5, 0, 0), (1, 1, 1))])
        return hulls

    def test_closed_cube(self):
        with tempfile.TemporaryDirectory() as tmp:
            model = os.path.join(tmp, "cube.off")
            write_off(model, CORNERS, QUADS)
            r = score(model, self.two_halves(tmp))
            self.assertTrue(r["closed"])
            self.assertLess(r["hull_outside_max"], 1e-9)
            self.assertLess(r["model_to_hulls_max"], 1e-9)
            self.assertGreater(r["iou"], 0.97)

    def test_cube_cracked_into_six_faces(self):
        # Each face its own corners, moved out by 1e-7 (CGAL's reader merges equal points): six
        # open shells, none of which winds half way around the middle of the cube (each about
        # 1/6 there); together they wind once.
        with tempfile.TemporaryDirectory() as tmp:
            model = os.path.join(tmp, "cracked.off")
            vertices, faces = [], []
            for q in QUADS:
                faces.append(tuple(len(vertices) + k for k in range(4)))
                c = [CORNERS[k] for k in q]
                axis = next(a for a in range(3) if len({p[a] for p in c}) == 1)
                shift = 1e-7 if c[0][axis] == 1 else -1e-7
                vertices.extend(tuple(p[a] + (shift if a == axis else 0) for a in range(3)) for p in c)
            write_off(model, vertices, faces)
            r = score(model, self.two_halves(tmp))
            self.assertFalse(r["closed"])
            self.assertIsNone(r["iou"])
            # Samples nearer the surface than 0.005 count their distance (no winding number asked).
            self.assertLess(r["hull_outside_max"], 0.0051)

    def test_open_box_and_a_hull_beyond_it(self):
        # The cube without its lid (z = 1) still bounds it; a hull reaching 0.5 above the lid plane
        # stands off it most at the middle of its top, sqrt(1/2) from the rim, in units of the
        # minimum enclosing sphere (radius sqrt(3)/2).
        with tempfile.TemporaryDirectory() as tmp:
            model = os.path.join(tmp, "open.off")
            write_off(model, CORNERS, [q for q in QUADS if q != (4, 5, 7, 6)])
            hulls = os.path.join(tmp, "tall.obj")
            write_hulls(hulls, [((0, 0, 0), (1, 1, 1.5))])
            r = score(model, hulls)
            self.assertFalse(r["closed"])
            self.assertAlmostEqual(r["hull_outside_max"], 0.5 ** 0.5 / (3 ** 0.5 / 2), delta=0.03)


if __name__ == "__main__":
    SCORE = sys.argv.pop(1)
    unittest.main()

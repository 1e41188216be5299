#!/usr/bin/python3
"""Tests of the benchmark helpers bench/compare_peers.py, bench/compare_assemblies.py and
bench/invariance.py (run by ctest)."""
import importlib.util
import math
import os
import tempfile
import unittest

BENCH = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "bench")


def load(name):
    spec = importlib.util.spec_from_file_location(name, os.path.join(BENCH, name + ".py"))
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    return mod


fid = load("fidelity")
inv = load("invariance")
import sys  # noqa: E402
sys.path.insert(0, BENCH)
asm = load("compare_assemblies")


def run(tau, parts, excess=0.05, iou=0.9):
    return {"tau": tau, "parts": parts, "excess": excess, "iou": iou}


class Fidelity(unittest.TestCase):
    """The comparison's rules (bench/fidelity.py, docs/BENCHMARKS.md): adjacent tau of one series,
    figures and parts from the same runs, an unbracketed pair a loss."""

    def test_log_linear_between_adjacent_tau(self):
        # parts = 100 * exp(-20 * excess) exactly: the interpolation must give it back.
        series = [run(t, 100 * math.exp(-20 * e), e) for t, e in ((0.1, 0.1), (0.05, 0.05), (0.02, 0.02))]
        v, kind, used = fid.parts_at(series, "excess", 0.07)
        self.assertEqual(kind, fid.BRACKETED)
        self.assertAlmostEqual(v, 100 * math.exp(-1.4), places=9)
        self.assertEqual([r["tau"] for r in used], [0.1, 0.05])

    def test_no_envelope_across_runs(self):
        # tau 0.07 sticks out further than tau 0.1 with more parts. The old envelope skipped it and
        # bracketed 20 -> 40 (about 25 parts at 0.05); by the rule the pair is the adjacent
        # 0.07 (misses) -> 0.05 (meets, and every finer run meets): between 30 and 40 parts.
        series = [run(0.14, 10, 0.10), run(0.1, 20, 0.06), run(0.07, 30, 0.08), run(0.05, 40, 0.03), run(0.035, 50, 0.02)]
        v, kind, used = fid.parts_at(series, "excess", 0.05)
        self.assertEqual([r["tau"] for r in used], [0.07, 0.05])
        self.assertGreater(v, 30)
        self.assertLessEqual(v, 40)

    def test_a_lucky_coarse_run_does_not_count(self):
        # tau 0.1 meets the IoU but 0.07 misses it again: the pair starts where every finer run meets.
        series = [run(0.2, 5, iou=0.80), run(0.1, 10, iou=0.95), run(0.07, 15, iou=0.85), run(0.05, 20, iou=0.95)]
        v, kind, used = fid.parts_at(series, "iou", 0.9)
        self.assertEqual([r["tau"] for r in used], [0.07, 0.05])
        self.assertAlmostEqual(v, math.exp(math.log(15) + 0.5 * math.log(20 / 15)), places=9)

    def test_figure_and_parts_from_the_same_runs(self):
        # The IoU pair and the excess pair are each read from the runs that cross that figure.
        series = [run(0.1, 10, 0.09, 0.85), run(0.05, 20, 0.04, 0.92)]
        for fig, target in (("iou", 0.9), ("excess", 0.05)):
            _, _, used = fid.parts_at(series, fig, target)
            for r in used:
                self.assertIn(r, series)

    def test_unbracketed_pair_is_a_loss(self):
        series = [run(0.1, 10, iou=0.8), run(0.05, 20, iou=0.9)]
        v, kind, _ = fid.parts_at(series, "iou", 0.95)
        self.assertEqual((v, kind), (20, fid.LOSS))
        # counted as at least 1 (acd needs more), even when acd's finest run has fewer parts
        self.assertEqual(fid.ratio(series, "iou", 40, 0.95), (1.0, fid.LOSS))
        self.assertEqual(fid.ratio(series, "iou", 10, 0.95), (2.0, fid.LOSS))
        # and a finest run that misses after coarser ones met is a loss too
        series = [run(0.1, 10, iou=0.96), run(0.05, 20, iou=0.9)]
        self.assertEqual(fid.parts_at(series, "iou", 0.95)[1], fid.LOSS)

    def test_coarsest_run_meeting_gives_an_upper_bound(self):
        series = [run(0.2, 6, 0.03), run(0.1, 12, 0.02)]
        self.assertEqual(fid.ratio(series, "excess", 12, 0.05), (0.5, fid.AT_MOST))

    def test_median_and_geomean(self):
        self.assertEqual(fid.median([3, 1, 2]), 2)
        self.assertEqual(fid.median([4, 1, 2, 3]), 2.5)
        self.assertAlmostEqual(fid.geomean([0.5, 2.0]), 1.0, places=12)


class Motions(unittest.TestCase):
    def test_random_rotations_are_proper_and_invertible(self):
        for seed in range(1, 9):
            R, t = inv.motion("random:%d" % seed, 3.0)
            for i in range(3):
                for j in range(3):
                    dot = sum(R[i][k] * R[j][k] for k in range(3))
                    self.assertAlmostEqual(dot, 1.0 if i == j else 0.0, places=12)
            det = (R[0][0] * (R[1][1] * R[2][2] - R[1][2] * R[2][1]) - R[0][1] * (R[1][0] * R[2][2] - R[1][2] * R[2][0])
                   + R[0][2] * (R[1][0] * R[2][1] - R[1][1] * R[2][0]))
            self.assertAlmostEqual(det, 1.0, places=12)
            p = (0.3, -1.7, 2.25)
            back = inv.unapply(R, t, inv.apply(R, t, p))
            self.assertLess(math.dist(back, p), 1e-12)

    def test_seeded_motions_repeat(self):
        self.assertEqual(inv.motion("random:3", 1.0), inv.motion("random:3", 1.0))
        self.assertNotEqual(inv.motion("random:3", 1.0), inv.motion("random:4", 1.0))

    def test_turn_is_exact_and_keeps_colours_and_faces(self):
        with tempfile.TemporaryDirectory() as d:
            src, dst = os.path.join(d, "a.off"), os.path.join(d, "b.off")
            open(src, "w").write("COFF\n# comment\n3 1 0\n0.1 -0.2 0.3 1 2 3 255\n1e-5 7 -0 4 5 6 255\n"
                                 "2 3 4 7 8 9 255\n3 0 1 2\n")
            inv.move(src, dst, "turn")
            _, _, verts, fidx = inv.read_off(dst)
            self.assertEqual(verts, [(0.2, 0.1, 0.3), (-7.0, 1e-5, -0.0), (-3.0, 2.0, 4.0)])
            lines = open(dst).read().split("\n")
            self.assertTrue(lines[3].endswith("1 2 3 255"))
            self.assertEqual(lines[fidx[0]], "3 0 1 2")

    def test_counts_on_the_header_line(self):
        with tempfile.TemporaryDirectory() as d:
            src = os.path.join(d, "a.off")
            open(src, "w").write("OFF 3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n")
            self.assertEqual(len(inv.read_off(src)[2]), 3)


class Comparison(unittest.TestCase):
    CUBE = ("OFF\n8 12 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n0 0 1\n1 0 1\n1 1 1\n0 1 1\n"
            "3 0 2 1\n3 0 3 2\n3 4 5 6\n3 4 6 7\n3 0 1 5\n3 0 5 4\n3 1 2 6\n3 1 6 5\n"
            "3 2 3 7\n3 2 7 6\n3 3 0 4\n3 3 4 7\n")

    def test_centroid_of_a_cube(self):
        with tempfile.TemporaryDirectory() as d:
            p = os.path.join(d, "c.off")
            open(p, "w").write(self.CUBE)
            for a, b in zip(inv.centroid(p), (0.5, 0.5, 0.5)):
                self.assertAlmostEqual(a, b, places=12)

    def test_matching_through_the_motion(self):
        R, t = inv.motion("random:5", 2.0)
        m = {"R": R, "t": t, "diagonal": 2.0}
        cents = [(0.1, 0.2, 0.3), (-0.5, 0.0, 0.4), (0.9, -0.9, 0.0)]
        orig = (0, [1.0, 2.0, 3.0], cents)
        # the moved run lists its components in another order
        moved = (0, [3.0, 1.0, 2.0], [inv.apply(R, t, cents[2]), inv.apply(R, t, cents[0]), inv.apply(R, t, cents[1])])
        self.assertEqual(inv.compare(orig, moved, m), (True, 0.0))
        off = (0, [3.0, 1.0, 2.0 * (1 + 1e-5)], moved[2])
        ok, worst = inv.compare(orig, off, m)
        self.assertFalse(ok)
        self.assertAlmostEqual(worst, 1e-5, places=12)
        self.assertFalse(inv.compare(orig, (0, [1.0, 2.0], moved[2][:2]), m)[0])


class Assemblies(unittest.TestCase):
    """bench/compare_assemblies.py reads acd-score's figures: an open model has no IoU but keeps its
    distances; the excess compared is the larger of the two distances."""

    def publish(self, d, run_json, score_json):
        import json
        os.makedirs(d, exist_ok=True)
        json.dump(run_json, open(os.path.join(d, "run.json"), "w"))
        if score_json is not None:
            json.dump(score_json, open(os.path.join(d, "score.json"), "w"))

    def test_scored_figures(self):
        with tempfile.TemporaryDirectory() as tmp:
            closed = os.path.join(tmp, "a")
            self.publish(closed, {"rc": 0, "seconds": 1.5}, {"hulls": 7, "hull_outside_max": 0.04, "hull_outside_p99": 0.02,
                                                            "model_to_hulls_max": 0.06, "iou": 0.9})
            f = asm.scored(closed)
            self.assertEqual((f["parts"], f["excess"], f["iou"]), (7, 0.06, 0.9))
            self.assertIn("7 · 0.040 / 0.020 · 0.060 · 0.900", asm.cell(f))
            open_model = os.path.join(tmp, "b")
            self.publish(open_model, {"rc": 8, "seconds": 1.0}, {"hulls": 3, "hull_outside_max": 0.2,
                                                                "hull_outside_p99": 0.1, "model_to_hulls_max": 0.0,
                                                                "iou": None})
            g = asm.scored(open_model)
            self.assertIsNone(g["iou"])
            self.assertIn("· – ·", asm.cell(g))
            self.assertIn("(exit 8)", asm.cell(g))
            failed = os.path.join(tmp, "c")
            self.publish(failed, {"rc": 2, "seconds": 0.1}, None)
            self.assertEqual(asm.cell(asm.scored(failed)), "exit 2, not scored")
            self.assertIsNone(asm.scored(os.path.join(tmp, "missing")))


if __name__ == "__main__":
    unittest.main()

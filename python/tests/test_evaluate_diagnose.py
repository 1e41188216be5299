"""acd.evaluate and acd.diagnose against `acd evaluate --json` and `acd info`."""
import json
import re

import numpy as np
import pytest

import acd
from conftest import l_shape, run_cli


def test_evaluate_matches_the_cli(cli, small_model, tmp_path):
    corpus_model = small_model
    code, _, err = run_cli(cli, "decompose", corpus_model, "-q", "-t", "0.1", "-o", tmp_path)
    assert code in (0, 4), err
    hulls = tmp_path / "hulls.obj"
    options = dict(samples=20000, surface_samples=2000, seed=7, threads=2)
    code, out, err = run_cli(cli, "evaluate", corpus_model, hulls, "--json", "--samples", 20000,
                             "--surface-samples", 2000, "--seed", 7, "--threads", 2)
    assert code == 0, err
    expected = json.loads(out)
    got = acd.evaluate(str(corpus_model), str(hulls), **options)
    for key in expected:
        if key != "seconds":
            assert got[key] == expected[key], key
    # The same hulls given as arrays (a Decomposition, or a list of meshes) measure the same.
    result = acd.decompose(corpus_model, tau=0.1)
    for hull_input in (result, result.hulls, [(h.vertices, h.faces) for h in result.hulls]):
        again = acd.evaluate(acd.read_mesh(corpus_model), hull_input, **options)
        assert again["iou"] == expected["iou"] and again["hulls"] == expected["hulls"]
        assert again["model"] is None and again["hulls_file"] is None


def test_evaluate_l_shape_hulls_cover_it_exactly():
    v, f = l_shape()
    result = acd.decompose(v, f)
    e = acd.evaluate((v, f), result, samples=20000, surface_samples=2000)
    assert e["hulls"] == 2
    assert e["misclassified_share"] == 0 and e["hull_outside_max"] < 1e-9


def test_evaluate_rejects_bad_options():
    v, f = l_shape()
    with pytest.raises(acd.Error):
        acd.evaluate((v, f), [(v, f)], samples=0)
    with pytest.raises(acd.Error):
        acd.evaluate((v, f), [])


def info_numbers(text):
    """{field: value} of the `acd info` lines that hold one number."""
    numbers = {}
    for line in text.splitlines()[1:]:
        m = re.match(r"\s+(.+?)\s{2,}(-?[\d.e+-]+)(\s|$)", line)
        if m:
            numbers[m.group(1).strip()] = float(m.group(2))
    return numbers


def test_diagnose_matches_acd_info(cli, corpus_model):
    code, out, err = run_cli(cli, "info", corpus_model)
    assert code == 0, err
    info = info_numbers(out)
    d = acd.diagnose(corpus_model)
    pairs = {"vertices": "vertices", "faces": "faces", "edges": "edges", "boundary edges": "boundary_edges",
             "non-manifold edges": "non_manifold_edges", "components": "components", "genus": "genus",
             "duplicate vertices": "duplicate_vertices", "degenerate faces": "degenerate_faces"}
    for label, key in pairs.items():
        assert d[key] == info[label], key
    assert d["volume"] == pytest.approx(info["volume"], rel=1e-8)
    assert d["area"] == pytest.approx(info["area"], rel=1e-8)
    assert d["solid_decomposition"] == ("solid decomposition   possible" in out)


def test_diagnose_reports_problems_instead_of_raising():
    v, f = l_shape()
    d = acd.diagnose(v, f[:-1])  # one face missing: open
    assert not d["closed"] and d["boundary_edges"] == 3 and d["genus"] is None
    nan = v.copy()
    nan[0, 0] = np.nan
    assert acd.diagnose(nan, f)["non_finite_vertices"] == 1
    closed = acd.diagnose(v, f)
    assert closed["closed"] and closed["genus"] == 0 and closed["volume"] == pytest.approx(3.0)
    assert closed["self_intersections"] == 0

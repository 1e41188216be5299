"""acd.decompose_exact and decompose(exact=True): the exact baselines of `acd decompose --exact`,
run in a worker process forked from the interpreter (sandbox/exact_solid)."""
import json
import threading

import numpy as np
import pytest

import acd
from conftest import cli_decompose, l_shape, run_cli, signed_volume, without_timing


@pytest.fixture
def l_file(tmp_path):
    path = tmp_path / "l.off"
    acd.write_mesh(path, *l_shape())
    return path


def test_solid_matches_the_cli(cli, l_file, tmp_path):
    """Pieces, total volume and report (except timings) as `acd decompose --exact`."""
    expected = cli_decompose(cli, l_file, tmp_path / "cli", "--exact")
    result = acd.decompose(l_file, exact=True)
    assert without_timing(result.report) == without_timing(expected)
    assert result.report["totals"]["finished"] and len(result.components) == expected["totals"]["components"] == 2
    # Volumes by our own formula: the pieces fill the L (volume 3) without overlapping.
    volume = sum(signed_volume(*piece) for piece in result.components)
    assert volume == pytest.approx(expected["totals"]["volume"], abs=1e-9)
    assert volume == pytest.approx(3.0, abs=1e-9)
    assert result.hulls == result.components  # a convex piece is its own hull


def test_arrays_and_the_function_match_the_path(l_file):
    from_path = acd.decompose_exact(l_file)
    from_arrays = acd.decompose_exact(*l_shape())
    assert from_arrays.report["model"] is None
    assert without_timing(from_arrays.report) == without_timing(from_path.report)
    for a, b in zip(from_arrays.components, from_path.components):
        assert np.array_equal(a.vertices, b.vertices) and np.array_equal(a.faces, b.faces)


def test_surface_matches_the_cli(cli, l_file, tmp_path):
    expected = cli_decompose(cli, l_file, tmp_path / "cli", "--exact", "--surface")
    result = acd.decompose(l_file, exact=True, surface=True)
    assert isinstance(result, acd.SurfaceDecomposition)
    assert without_timing(result.report) == without_timing(expected)
    assert len(result.components) == expected["totals"]["components"]
    # Every face of the input in exactly one patch.
    assert sorted(np.concatenate(result.patch_faces).tolist()) == list(range(len(result.surface.faces)))


def test_worker_runs_from_threads(l_file):
    """The worker is forked from threads of the interpreter, which runs on (the GIL is released)."""
    reports, stages = [None] * 3, []

    def run(k):
        reports[k] = acd.decompose_exact(l_file, progress=lambda stage, seconds: stages.append(stage)).report

    threads = [threading.Thread(target=run, args=(k,)) for k in range(3)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    assert all(r["totals"]["finished"] and r["totals"]["components"] == 2 for r in reports)
    assert all(isinstance(stage, str) for stage in stages)


def test_time_limit_stops_it_as_the_cli(cli, corpus_model, tmp_path):
    """A cap is no error: finished is false and the note says where it stopped (the CLI exits 4)."""
    code, _, err = run_cli(cli, "decompose", corpus_model, "-q", "-o", tmp_path / "cli", "--exact",
                           "--exact-time-limit", "0.5")
    assert code == 4, err
    expected = json.loads((tmp_path / "cli" / "report.json").read_text())["totals"]
    with pytest.warns(RuntimeWarning, match="not finished"):
        result = acd.decompose(corpus_model, exact=True, exact_time_limit=0.5)
    totals = result.report["totals"]
    assert totals["finished"] is False and expected["finished"] is False
    assert totals["note"].startswith("not finished within 0.5 s") and expected["note"].startswith(
        "not finished within 0.5 s")
    for key in ("components_written", "solids", "unfinished_solids"):
        assert totals[key] == expected[key], key
    assert len(result.components) == totals["components_written"]


def cli_message(cli, model, tmp_path, *args):
    code, _, err = run_cli(cli, "decompose", model, "-q", "-o", tmp_path / "bad", "--exact", *args)
    assert code != 0
    return err.strip()


@pytest.mark.parametrize("keyword, option", [("exact_time_limit", "--exact-time-limit"),
                                             ("exact_memory", "--exact-memory")])
def test_bad_cap_raises_the_cli_message(cli, l_file, tmp_path, keyword, option):
    message = cli_message(cli, l_file, tmp_path, option, "-1")
    with pytest.raises(ValueError) as raised:
        acd.decompose(l_file, exact=True, **{keyword: -1})
    assert isinstance(raised.value, acd.Error) and raised.value.code == acd.StatusCode.InvalidParameter
    # The command names its options, the function its keywords.
    python_names = message.replace("--exact-time-limit", "exact_time_limit").replace("--exact-memory", "exact_memory")
    assert python_names.endswith(str(raised.value))


def test_bad_tolerance_raises_the_cli_message(cli, l_file, tmp_path):
    message = cli_message(cli, l_file, tmp_path, "--surface", "--exact-tolerance", "-1")
    with pytest.raises(acd.Error) as raised:
        acd.decompose_exact(l_file, surface=True, exact_tolerance=-1)
    assert message.endswith(str(raised.value))


def test_solid_only_options_refused(cli, l_file, tmp_path):
    """As the command refuses --max-hulls, --tau-abs, --max-hull-vertices with --exact."""
    code, _, _ = run_cli(cli, "decompose", l_file, "-q", "-o", tmp_path / "bad", "--exact", "--max-hulls", "3")
    assert code != 0
    for keyword, value in (("max_hulls", 3), ("tau_abs", 0.1), ("max_hull_vertices", 8)):
        with pytest.raises(acd.Error, match="solid decomposition only"):
            acd.decompose(l_file, exact=True, **{keyword: value})


def test_open_mesh_refused_with_no_fill_holes(cli, tmp_path):
    vertices, faces = l_shape()
    path = tmp_path / "open.off"
    acd.write_mesh(path, vertices, faces[:-2])  # one side face pair missing
    message = cli_message(cli, path, tmp_path, "--no-fill-holes")
    with pytest.raises(acd.Error) as raised:
        acd.decompose(path, exact=True, no_fill_holes=True)
    assert message.endswith(str(raised.value))
    assert acd.decompose(path, exact=True).report["input"]["holes_filled"] == 1

"""The simulator keywords of acd.decompose (tau_abs, max_hulls, max_hull_vertices, density) and
acd.write_simulator_files give what `acd decompose` with the same options gives."""
import math
import warnings

import numpy as np
import pytest

import acd
from conftest import cli_decompose, l_shape, run_cli, without_timing

V, F = l_shape()


def decompose_quietly(*args, **options):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", RuntimeWarning)  # a budget above tau is expected here
        return acd.decompose(*args, **options)


def same_hulls_as_written(result, hulls_obj):
    written = acd._core.read_obj_objects(str(hulls_obj))
    assert len(written) == len(result.hulls)
    for (v, f), hull in zip(written, result.hulls):
        np.testing.assert_array_equal(v, hull.vertices)
        np.testing.assert_array_equal(f, hull.faces)


def test_capped_and_budgeted_decomposition_is_the_clis(cli, corpus_model, tmp_path):
    cli_report = cli_decompose(cli, corpus_model, tmp_path, "-t", "0.05", "--max-hulls", "12",
                               "--max-hull-vertices", "16", "--density", "500")
    result = decompose_quietly(corpus_model, tau=0.05, max_hulls=12, max_hull_vertices=16, density=500)
    assert len(result.hulls) == len(result.components) == cli_report["totals"]["components"] == 12
    vertex_counts = [len(h.vertices) for h in result.hulls]
    assert vertex_counts == [c["hull_vertices"] for c in cli_report["components"]]
    assert max(vertex_counts) <= 16
    assert without_timing(result.report) == without_timing(cli_report)
    for section in ("hull_budget", "hull_vertex_cap", "mass_properties"):
        assert section in result.report
    assert result.report["mass_properties"]["density"] == 500
    same_hulls_as_written(result, tmp_path / "hulls.obj")


def test_tau_abs_is_the_clis(cli, small_model, tmp_path):
    cli_report = cli_decompose(cli, small_model, tmp_path, "--tau-abs", "0.05")
    result = acd.decompose(small_model, tau_abs=0.05)
    assert without_timing(result.report) == without_timing(cli_report)
    assert result.report["tau_abs"]["given"] == 0.05
    assert result.report["parameters"]["tau"] == pytest.approx(0.05 / result.report["tau_abs"]["normalised_unit_in_input_units"])
    same_hulls_as_written(result, tmp_path / "hulls.obj")


def test_vertex_cap_on_arrays():
    result = acd.decompose(V, F, max_hull_vertices=4)
    assert len(result.hulls) == 2
    assert all(len(h.vertices) <= 4 for h in result.hulls)
    assert result.report["hull_vertex_cap"]["within_cap"] == 2
    # Each capped hull contains its component: at least its volume.
    for c in result.report["components"]:
        assert c["hull_volume"] >= c["uncapped_hull_volume"] > 0


def test_budget_above_tau_warns(small_model):
    with pytest.warns(RuntimeWarning, match="max_hulls=1"):
        result = acd.decompose(small_model, tau=0.05, max_hulls=1)
    assert len(result.hulls) == 1
    assert result.report["hull_budget"]["exceeds_tau"]


def test_simulator_files_are_the_clis(cli, small_model, tmp_path):
    formats = "urdf,mjcf,sdf,obj,glb"
    cli_out = tmp_path / "cli"
    cli_report = cli_decompose(cli, small_model, cli_out, "-t", "0.1", "--max-hull-vertices", "24",
                               "--density", "250", "--format", formats)
    result = acd.decompose(small_model, tau=0.1, max_hull_vertices=24, density=250)
    written = acd.write_simulator_files(tmp_path / "py", result, small_model, formats)
    assert written == cli_report["outputs"]["files"]
    for name in written:
        assert (tmp_path / "py" / name).read_bytes() == (cli_out / name).read_bytes(), name


# Values `acd decompose` refuses with exit 3, and the keyword arguments that say the same.
BAD_VALUES = [
    (dict(max_hulls=0), ["--max-hulls", "0"]),
    (dict(max_hulls=-2), ["--max-hulls=-2"]),
    (dict(max_hull_vertices=3), ["--max-hull-vertices", "3"]),
    (dict(density=0.0), ["--density", "0"]),
    (dict(density=-1.0), ["--density=-1"]),
    (dict(density=math.nan), None),
    (dict(tau_abs=0.0), ["--tau-abs", "0"]),
    (dict(tau_abs=-1.0), ["--tau-abs=-1"]),
    (dict(tau_abs=math.inf), None),
    (dict(tau_abs=1000.0), ["--tau-abs", "1000"]),
    (dict(tau=0.1, tau_abs=0.2), None),  # either tau or tau_abs
]


@pytest.mark.parametrize("options, cli_args", BAD_VALUES, ids=[str(o) for o, _ in BAD_VALUES])
def test_bad_values_raise_value_error(options, cli_args, cli, small_model, tmp_path):
    with pytest.raises(ValueError) as error:
        acd.decompose(small_model, **options)
    assert isinstance(error.value, acd.Error)
    assert error.value.code == acd.StatusCode.InvalidParameter
    if cli_args is not None:
        code, _, err = run_cli(cli, "decompose", small_model, "-q", "-o", tmp_path / "out", *cli_args)
        assert code == 3
        assert err.strip() == f"acd: invalid parameter: {error.value}"


def test_wrong_types_and_formats(tmp_path):
    with pytest.raises(TypeError, match="max_hulls"):
        acd.decompose(V, F, max_hulls="many")
    result = acd.decompose(V, F)
    with pytest.raises(ValueError, match="unknown format 'dae'"):
        acd.write_simulator_files(tmp_path, result, (V, F), ["urdf", "dae"])
    assert not list(tmp_path.iterdir())

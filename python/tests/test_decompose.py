"""acd.decompose and acd.decompose_surface: known answers, the CLI's results, threads, progress, GIL."""
import threading
import time

import numpy as np
import pytest

import acd
from conftest import cli_decompose, l_shape, signed_volume, without_timing


def convexity_violation(vertices, faces):
    """Largest distance of a hull vertex outside the plane of a hull face (0 for a convex hull)."""
    a, b, c = (vertices[faces[:, k]] for k in range(3))
    normals = np.cross(b - a, c - a)
    normals /= np.linalg.norm(normals, axis=1)[:, None]
    return float(np.max(np.einsum("fk,vk->fv", normals, vertices) - np.einsum("fk,fk->f", normals, a)[:, None]))


def test_l_shape_gives_two_convex_hulls():
    vertices, faces = l_shape()
    result = acd.decompose(vertices, faces, tau=0.05)
    assert len(result.hulls) == 2 and len(result.components) == 2
    for hull in result.hulls:
        assert convexity_violation(hull.vertices, hull.faces) < 1e-9
    # The pieces are cut from the L: their volumes add up to its volume, 3, and each is a box.
    volumes = sorted(signed_volume(*c) for c in result.components)
    assert sum(volumes) == pytest.approx(3.0, rel=1e-9)
    for c, h in zip(result.components, result.hulls):
        assert signed_volume(*c) == pytest.approx(signed_volume(*h), rel=1e-9)
    assert result.report["totals"]["components"] == 2
    assert result.report["model"] is None
    assert result.report["version"] == acd.__version__


def test_same_result_as_the_cli(cli, corpus_model, tmp_path):
    """Report (except timings), components and hulls identical to `acd decompose` at tau = 0.05."""
    cli_report = cli_decompose(cli, corpus_model, tmp_path, "-t", "0.05")
    result = acd.decompose(str(corpus_model), tau=0.05)
    assert result.report["model"] == str(corpus_model) == cli_report["model"]
    assert without_timing(result.report) == without_timing(cli_report)
    assert len(result.components) == cli_report["totals"]["components"]
    assert [c["volume"] for c in result.report["components"]] == [c["volume"] for c in cli_report["components"]]
    for i, component in enumerate(result.components):
        written = acd.read_mesh(tmp_path / f"component_{i:03d}.off")
        np.testing.assert_array_equal(written.vertices, component.vertices)
        np.testing.assert_array_equal(written.faces, component.faces)
    hulls = acd._core.read_obj_objects(str(tmp_path / "hulls.obj"))
    assert len(hulls) == len(result.hulls)
    for (v, f), hull in zip(hulls, result.hulls):
        np.testing.assert_array_equal(v, hull.vertices)
        np.testing.assert_array_equal(f, hull.faces)


def test_surface_same_result_as_the_cli(cli, small_model, tmp_path):
    cli_report = cli_decompose(cli, small_model, tmp_path, "--surface", "-t", "0.1")
    result = acd.decompose_surface(small_model, tau=0.1)
    assert without_timing(result.report) == without_timing(cli_report)
    # The patches partition the repaired surface's faces.
    faces = np.sort(np.concatenate(result.patch_faces))
    np.testing.assert_array_equal(faces, np.arange(len(result.surface.faces)))
    assert len(result.hulls) == len(result.components) == cli_report["totals"]["components"]


def test_thread_count_does_not_change_the_result(small_model):
    mesh = acd.read_mesh(small_model)
    runs = [acd.decompose(mesh, tau=0.05, threads=n) for n in (1, 2, 3)]
    first = runs[0]
    for other in runs[1:]:
        a, b = without_timing(first.report), without_timing(other.report)
        a["parameters"].pop("threads"), b["parameters"].pop("threads")
        assert a == b
        for x, y in zip(first.components + first.hulls, other.components + other.hulls):
            np.testing.assert_array_equal(x.vertices, y.vertices)
            np.testing.assert_array_equal(x.faces, y.faces)


def test_progress_is_reported_and_its_exceptions_raised():
    calls = []
    acd.decompose(*l_shape(), progress=lambda done, pending: calls.append((done, pending)))
    assert calls and all(isinstance(d, int) and isinstance(p, int) for d, p in calls)
    assert calls[-1] == (2, 0)

    def broken(done, pending):
        raise KeyError("stop")
    with pytest.raises(KeyError, match="stop"):
        acd.decompose(*l_shape(), progress=broken)


def test_the_gil_is_released_while_decomposing(small_model):
    mesh = acd.read_mesh(small_model)
    finished = threading.Event()
    worker = threading.Thread(target=lambda: (acd.decompose(mesh, tau=0.05, threads=1), finished.set()))
    ticks = 0
    start = time.perf_counter()
    worker.start()
    while not finished.is_set() and worker.is_alive():
        ticks += 1
        time.sleep(0.001)
    worker.join()
    elapsed = time.perf_counter() - start
    # With the GIL held for the whole decomposition this loop would barely run at all
    assert elapsed > 0.2
    # (it could only run during the few progress callbacks); released, it ticks about 1000 times a second.
    assert ticks > 100 * elapsed

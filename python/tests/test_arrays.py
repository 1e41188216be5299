"""numpy in and out: dtypes, shapes, layouts, and a trimesh-style round trip."""
import numpy as np
import pytest

import acd
from conftest import l_shape, signed_volume


class TrimeshLike:
    """What code written for trimesh hands over: an object with .vertices (float64) and .faces (int64)."""

    def __init__(self, vertices, faces):
        self.vertices = np.asarray(vertices, dtype=np.float64)
        self.faces = np.asarray(faces, dtype=np.int64)

    @property
    def volume(self):
        return signed_volume(self.vertices, self.faces)


def check_mesh_arrays(mesh):
    assert isinstance(mesh, acd.Mesh)
    v, f = mesh
    assert v.dtype == np.float64 and v.ndim == 2 and v.shape[1] == 3 and v.flags.c_contiguous
    assert f.dtype == np.int64 and f.ndim == 2 and f.shape[1] == 3 and f.flags.c_contiguous
    if len(f):
        assert f.min() >= 0 and f.max() < len(v)


def test_result_types_and_shapes():
    result = acd.decompose(*l_shape())
    assert isinstance(result, acd.Decomposition) and isinstance(result.report, dict)
    parts, hulls, report = result  # unpacks like a tuple
    assert len(parts) == len(hulls) == report["totals"]["components"]
    for mesh in parts + hulls:
        check_mesh_arrays(mesh)
    for mesh, entry in zip(parts, report["components"]):
        assert len(mesh.vertices) == entry["vertices"] and len(mesh.faces) == entry["faces"]


@pytest.mark.parametrize("vertex_type", [np.float64, np.float32, np.int32, np.int64])
@pytest.mark.parametrize("face_type", [np.int64, np.int32, np.uint32, np.int16])
def test_input_dtypes_give_the_same_result(vertex_type, face_type):
    v, f = l_shape()  # integer coordinates: every dtype holds them exactly
    expected = acd.decompose(v, f)
    got = acd.decompose(v.astype(vertex_type), f.astype(face_type))
    for a, b in zip(expected.hulls, got.hulls):
        np.testing.assert_array_equal(a.vertices, b.vertices)
        np.testing.assert_array_equal(a.faces, b.faces)


def test_input_layouts_and_containers():
    v, f = l_shape()
    expected = acd.decompose(v, f).report["totals"]
    inputs = [
        (np.asfortranarray(v), np.asfortranarray(f)),
        (np.hstack([v, v])[:, :3], f),                    # non-contiguous view
        (v.tolist(), f.tolist()),                         # nested lists
    ]
    for vertices, faces in inputs:
        assert acd.decompose(vertices, faces).report["totals"] == pytest.approx(expected)
    assert acd.decompose((v, f)).report["totals"] == pytest.approx(expected)
    assert acd.decompose(acd.Mesh(v, f)).report["totals"] == pytest.approx(expected)


def test_trimesh_style_round_trip(tmp_path):
    """Mesh object in, hulls back into mesh objects; volumes by our own formula match the report."""
    model = TrimeshLike(*l_shape())
    result = acd.decompose(model, tau=0.05)
    scale = result.report["input"]["normalization"]["scale"]
    hull_objects = [TrimeshLike(h.vertices, h.faces) for h in result.hulls]
    for hull, entry in zip(hull_objects, result.report["components"]):
        # The report is in normalised units: x_normalised = (x - center) * scale.
        assert hull.volume * scale**3 == pytest.approx(entry["hull_volume"], rel=1e-9)
    assert sum(TrimeshLike(*c).volume for c in result.components) == pytest.approx(model.volume, rel=1e-9)
    # Arrays survive a file round trip exactly.
    for suffix in (".off", ".obj", ".ply", ".stl"):
        path = tmp_path / f"hull{suffix}"
        acd.write_mesh(path, hull_objects[0])
        back = acd.read_mesh(path)
        check_mesh_arrays(back)
        assert signed_volume(*back) == pytest.approx(hull_objects[0].volume, rel=1e-6)
        if suffix in (".off", ".obj", ".ply"):
            np.testing.assert_array_equal(back.vertices, hull_objects[0].vertices)
            np.testing.assert_array_equal(back.faces, hull_objects[0].faces)


def test_surface_result_types():
    result = acd.decompose_surface(*l_shape(), tau=0.05)
    assert isinstance(result, acd.SurfaceDecomposition)
    for mesh in result.components + result.hulls + [result.surface]:
        check_mesh_arrays(mesh)
    for faces in result.patch_faces:
        assert faces.dtype == np.int64 and faces.ndim == 1

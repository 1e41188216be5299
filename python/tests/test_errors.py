"""Bad input raises acd.Error (a ValueError) or TypeError with a clear message; nothing aborts."""
import subprocess
import sys

import numpy as np
import pytest

import acd
from conftest import l_shape, run_cli

V, F = l_shape()


def with_vertex(index, value):
    v = V.copy()
    v[index] = value
    return v


def with_face(index, value):
    f = F.copy()
    f[index] = value
    return f


BAD_MESHES = {
    "non-finite vertex": (with_vertex(3, [np.nan, 0, 0]), F, acd.StatusCode.NonFiniteVertex),
    "infinite vertex": (with_vertex(0, [np.inf, 0, 0]), F, acd.StatusCode.NonFiniteVertex),
    "index out of range": (V, with_face(2, [0, 1, 99]), acd.StatusCode.IndexOutOfRange),
    "negative index": (V, with_face(2, [0, -1, 2]), acd.StatusCode.IndexOutOfRange),
    "index beyond int": (V, with_face(2, [0, 1, 2**40]), acd.StatusCode.IndexOutOfRange),
    "no faces": (V, np.zeros((0, 3), np.int64), acd.StatusCode.EmptyMesh),
}
# Meshes the repairs may accept: the binding must do what the command does (compared below).
REPAIRABLE = {
    "non-manifold edge": (np.vstack([V, [[0.5, -1, 0.5]]]), np.vstack([F, [[0, 1, 12]]]), None),
}


def write_off(path, vertices, faces):
    """OFF written here (not by the library), so that the CLI reads exactly these numbers."""
    lines = ["OFF", f"{len(vertices)} {len(faces)} 0"]
    lines += [" ".join(repr(float(x)) for x in v) for v in vertices]
    lines += ["3 " + " ".join(str(int(i)) for i in f) for f in faces]
    path.write_text("\n".join(lines) + "\n")


@pytest.mark.parametrize("name", BAD_MESHES)
def test_bad_mesh_raises_the_library_error(name):
    vertices, faces, code = BAD_MESHES[name]
    with pytest.raises(acd.Error) as error:
        acd.decompose(vertices, faces)
    assert isinstance(error.value, ValueError)
    assert str(error.value)  # the library's one-line message
    if code is not None:
        assert error.value.code == code


@pytest.mark.parametrize("name", list(BAD_MESHES) + list(REPAIRABLE))
def test_bad_mesh_file_gets_the_cli_message(name, cli, tmp_path):
    """The same mesh as a file: the binding refuses it exactly when `acd decompose` does, with its message."""
    vertices, faces, _ = {**BAD_MESHES, **REPAIRABLE}[name]
    path = tmp_path / "bad.off"
    write_off(path, vertices, faces)
    code, _, err = run_cli(cli, "decompose", path, "-q", "-o", tmp_path / "out")
    if code in (0, 4):  # the CLI repairs it: so must the binding
        acd.decompose(path)
        return
    with pytest.raises(acd.Error) as error:
        acd.decompose(path)
    message = str(error.value)
    assert err.strip() in (f"acd: {message}", f"acd: {path}: {message}")


def test_open_mesh_is_refused_when_holes_may_not_be_filled():
    with pytest.raises(acd.Error) as error:
        acd.decompose(V, F[:-1], no_fill_holes=True, no_repair=True)
    assert error.value.code == acd.StatusCode.OpenMesh


@pytest.mark.parametrize("options", [dict(tau=-1), dict(tau=float("nan")), dict(tau=0.05, epsilon=0.5),
                                     dict(threads=-2), dict(delta=-0.5)])
def test_invalid_parameter(options):
    with pytest.raises(acd.Error) as error:
        acd.decompose(V, F, **options)
    assert error.value.code == acd.StatusCode.InvalidParameter


@pytest.mark.parametrize("vertices, faces", [
    (V[:, :2], F),                      # 2-D points
    (V, F[:, :2]),                      # not triangles
    (V.ravel(), F),                     # flat
    (V, F.astype(np.float64)),          # float indices
    (V.astype(str), F),                 # not numbers
    (V, F.astype(bool)),
])
def test_bad_array_shape_or_dtype_raises_value_error(vertices, faces):
    with pytest.raises(ValueError):
        acd.decompose(vertices, faces)


def test_unknown_keyword_or_wrong_type_raises_type_error():
    with pytest.raises(TypeError, match="taux"):
        acd.decompose(V, F, taux=0.1)
    with pytest.raises(TypeError, match="threads"):
        acd.decompose(V, F, threads="two")
    with pytest.raises(TypeError):
        acd.decompose(42)


def test_file_errors_carry_the_cli_message(cli, tmp_path):
    garbage = tmp_path / "garbage.off"
    garbage.write_text("OFF\n3 1 0\n0 0 0\n1 0\n")
    for path in (tmp_path / "missing.off", tmp_path / "model.xyz", garbage):
        with pytest.raises(acd.Error) as error:
            acd.decompose(path)
        code, _, err = run_cli(cli, "decompose", path, "-q", "-o", tmp_path / "out")
        assert code == 2
        # The CLI prints "acd: MESSAGE" (the message names the file): the same message.
        assert err.strip() == f"acd: {error.value}"


def test_errors_never_abort_the_interpreter():
    """Every bad call in a fresh interpreter: it must end normally, having caught every error."""
    script = """
import numpy as np, acd, sys
sys.path.insert(0, {here!r})
from test_errors import BAD_MESHES, V, F
caught = 0
for vertices, faces, _ in BAD_MESHES.values():
    for call in (acd.decompose, acd.decompose_surface, acd.diagnose):
        try:
            call(vertices, faces)
        except ValueError:
            caught += 1
for call in (lambda: acd.evaluate((V, F), [(V[:3], F[:1])]), lambda: acd.evaluate((V, F), []),
             lambda: acd.read_mesh("/nonexistent.off"), lambda: acd.decompose_surface(V, F, tau=0)):
    try:
        call()
    except ValueError:
        caught += 1
print(caught)
""".format(here=str(__import__("pathlib").Path(__file__).parent))
    p = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True, timeout=300)
    assert p.returncode == 0, p.stderr
    assert int(p.stdout.split()[-1]) >= 2 * len(BAD_MESHES) + 3


def collada_cube(indices):
    """A unit cube as COLLADA; `indices` is the text of its <p> element."""
    return f"""<?xml version="1.0" encoding="utf-8"?>
<COLLADA xmlns="http://www.collada.org/2005/11/COLLADASchema" version="1.4.1">
<library_geometries><geometry id="g"><mesh>
<source id="p"><float_array id="pa" count="24">0 0 0 1 0 0 0 1 0 1 1 0 0 0 1 1 0 1 0 1 1 1 1 1</float_array>
<technique_common><accessor source="#pa" count="8" stride="3">
<param name="X" type="float"/><param name="Y" type="float"/><param name="Z" type="float"/>
</accessor></technique_common></source>
<vertices id="v"><input semantic="POSITION" source="#p"/></vertices>
<triangles count="12"><input semantic="VERTEX" source="#v" offset="0"/><p>{indices}</p></triangles>
</mesh></geometry></library_geometries>
<library_visual_scenes><visual_scene id="s"><node id="n"><instance_geometry url="#g"/></node></visual_scene>
</library_visual_scenes><scene><instance_visual_scene url="#s"/></scene>
</COLLADA>
"""


def test_a_scene_that_exhausts_assimp_is_refused_not_held(tmp_path):
    # assimp 5.2.5 asks for about 19 GB on this file; the module reads scenes in a capped child.
    path = tmp_path / "bomb.dae"
    path.write_text(collada_cube("0 1x0 3 1 4 5 7 4 7 6 0 1 5 0 5 4 2 6 7 2 7 3 0 4 6 0 6 2 1 3 7 1 7 5"))
    with pytest.raises(acd.Error, match="the scene reader \\(assimp\\) needed more than"):
        acd.read_mesh(str(path))
    good = tmp_path / "cube.dae"
    good.write_text(collada_cube("0 2 3 0 3 1 4 5 7 4 7 6 0 1 5 0 5 4 2 6 7 2 7 3 0 4 6 0 6 2 1 3 7 1 7 5"))
    vertices, faces = acd.read_mesh(str(good))
    assert vertices.shape == (8, 3) and faces.shape == (12, 3)

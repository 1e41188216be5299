"""decompose(path, per_mesh=True): every mesh of a scene file on its own, as `acd decompose --per-mesh`."""
import base64
import json
import pathlib

import numpy as np
import pytest

import acd
from conftest import l_shape, run_cli, without_timing


def box(lo, hi):
    """An axis-aligned box, 8 vertices and 12 outward triangles."""
    vertices = np.array([(x, y, z) for x in (lo[0], hi[0]) for y in (lo[1], hi[1]) for z in (lo[2], hi[2])], float)
    faces = [(0, 1, 3), (0, 3, 2), (4, 6, 7), (4, 7, 5), (0, 4, 5), (0, 5, 1),
             (2, 3, 7), (2, 7, 6), (0, 2, 6), (0, 6, 4), (1, 5, 7), (1, 7, 3)]
    return vertices, np.array(faces, np.int64)


def parts():
    """(name, vertices, faces): an L (2 parts at the default tau), a box beside it (1 part)."""
    return [("ell", *l_shape()), ("crate", *box((4, 0, 0), (5, 2, 3)))]


def write_obj_objects(path):
    lines, base = [], 1
    for name, vertices, faces in parts():
        lines.append(f"o {name}")
        lines += [f"v {x:.17g} {y:.17g} {z:.17g}" for x, y, z in vertices]
        lines += [f"f {a + base} {b + base} {c + base}" for a, b, c in faces]
        base += len(vertices)
    path.write_text("\n".join(lines) + "\n")


def write_gltf(path):
    """glTF 2 with its buffer embedded: one node per mesh, the box placed twice (the second by a translation)."""
    blob, views, accessors, meshes = b"", [], [], []
    for name, vertices, faces in parts():
        for data, target, kind, component in ((vertices.astype("<f4"), 34962, "VEC3", 5126),
                                              (faces.astype("<u4").reshape(-1), 34963, "SCALAR", 5125)):
            views.append({"buffer": 0, "byteOffset": len(blob), "byteLength": data.nbytes, "target": target})
            accessor = {"bufferView": len(views) - 1, "componentType": component, "count": len(data), "type": kind}
            if kind == "VEC3":
                accessor |= {"min": data.min(axis=0).tolist(), "max": data.max(axis=0).tolist()}
            accessors.append(accessor)
            blob += data.tobytes()
        meshes.append({"name": f"{name}_mesh", "primitives": [{"attributes": {"POSITION": len(accessors) - 2},
                                                                "indices": len(accessors) - 1}]})
    nodes = [{"name": "ell", "mesh": 0}, {"name": "crate", "mesh": 1},
             {"name": "crate2", "mesh": 1, "translation": [0, 5, 0]}]
    gltf = {"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0, 1, 2]}], "nodes": nodes,
            "meshes": meshes, "accessors": accessors, "bufferViews": views,
            "buffers": [{"byteLength": len(blob),
                         "uri": "data:application/octet-stream;base64," + base64.b64encode(blob).decode()}]}
    path.write_text(json.dumps(gltf))


def cli_per_mesh(cli, scene, out):
    """[(mesh name, report.json)] from OUT/NNN_NAME/, in the command's order."""
    code, _, err = run_cli(cli, "decompose", scene, "-q", "-o", out, "--per-mesh")
    assert code == 0, err
    folders = sorted(p for p in pathlib.Path(out).iterdir() if p.is_dir())
    reports = [json.loads((folder / "report.json").read_text()) for folder in folders]
    return [(report["mesh"], report) for report in reports]


@pytest.mark.parametrize("writer, suffix, names, counts", [
    (write_obj_objects, ".obj", ["ell", "crate"], [2, 1]),
    (write_gltf, ".gltf", ["ell/ell_mesh", "crate/crate_mesh", "crate2/crate_mesh"], [2, 1, 1]),
])
def test_per_mesh_matches_the_cli(cli, tmp_path, writer, suffix, names, counts):
    scene = tmp_path / f"scene{suffix}"
    writer(scene)
    expected = cli_per_mesh(cli, scene, tmp_path / "cli")
    results = acd.decompose(scene, per_mesh=True)
    assert [r.name for r in results] == [name for name, _ in expected] == names
    assert [len(r.decomposition.hulls) for r in results] == counts
    for result, (_, report) in zip(results, expected):
        assert result.error is None
        assert result.decomposition.report["mesh"] == result.name
        assert without_timing(result.decomposition.report) == without_timing(report)
    # Without per_mesh the meshes are one model, as without --per-mesh.
    merged = acd.decompose(scene)
    assert "mesh" not in merged.report
    assert merged.report["input"]["faces"] == sum(r.decomposition.report["input"]["faces"] for r in results)


def test_per_mesh_of_a_single_mesh_file(tmp_path):
    path = tmp_path / "ell.off"
    acd.write_mesh(path, *l_shape())
    [result] = acd.decompose(path, per_mesh=True)
    assert result.name == "ell" and len(result.decomposition.hulls) == 2


def test_per_mesh_needs_a_file_and_solid_acd(tmp_path):
    scene = tmp_path / "scene.obj"
    write_obj_objects(scene)
    with pytest.raises(TypeError, match="path"):
        acd.decompose(*l_shape(), per_mesh=True)
    for mode in ("exact", "surface"):
        with pytest.raises(acd.Error, match="per_mesh applies to solid decomposition only"):
            acd.decompose(scene, per_mesh=True, **{mode: True})
    with pytest.raises(acd.Error, match="tau"):
        acd.decompose(scene, per_mesh=True, tau=-1)  # checked before anything is read, as by the command


def test_a_refused_mesh_does_not_stop_the_others(cli, tmp_path):
    """With no_wrap an open triangle is refused; the L before it is still decomposed, as by the command."""
    scene = tmp_path / "scene.obj"
    write_obj_objects(scene)
    with scene.open("a") as f:
        f.write("o flat\nv 9 0 0\nv 10 0 0\nv 9 1 0\nf 15 16 17\n")
    code, _, err = run_cli(cli, "decompose", scene, "-q", "-o", tmp_path / "cli", "--per-mesh", "--no-wrap")
    assert code != 0 and not (tmp_path / "cli" / "002_flat").exists()
    with pytest.warns(RuntimeWarning, match="mesh flat"):
        results = acd.decompose(scene, per_mesh=True, no_wrap=True)
    assert [r.name for r in results] == ["ell", "crate", "flat"]
    assert [len(r.decomposition.hulls) for r in results[:2]] == [2, 1]
    assert results[2].decomposition is None and results[2].error.code == acd.StatusCode.OpenMesh
    assert str(results[2].error) in err

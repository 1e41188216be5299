"""Meshes as numpy arrays: the Mesh pair, and the checks every entry point applies to its input."""
import os
from typing import NamedTuple

import numpy as np

from . import _core


class Mesh(NamedTuple):
    """A triangle mesh: ``vertices`` (n, 3) float64 and ``faces`` (m, 3) int64, counter-clockwise
    seen from outside. The same layout as ``trimesh.Trimesh(vertices, faces)``."""

    vertices: np.ndarray
    faces: np.ndarray


def checked_arrays(vertices, faces):
    """(vertices float64 (n, 3), faces int64 (m, 3)), contiguous; ValueError when they cannot be."""
    v = np.asarray(vertices)
    f = np.asarray(faces)
    if v.ndim != 2 or v.shape[1] != 3:
        raise ValueError(f"vertices must have shape (n, 3), not {v.shape}")
    if v.dtype.kind not in "fiu":
        raise ValueError(f"vertices must be real numbers, not {v.dtype}")
    if f.size == 0:
        f = f.reshape(0, 3)
    if f.ndim != 2 or f.shape[1] != 3:
        raise ValueError(f"faces must have shape (m, 3) (triangles), not {f.shape}")
    if f.dtype.kind not in "iu":
        raise ValueError(f"faces must be integer vertex indices, not {f.dtype}")
    return np.ascontiguousarray(v, dtype=np.float64), np.ascontiguousarray(f, dtype=np.int64)


def resolve(mesh, faces=None):
    """(vertices, faces, path) from a file path, a Mesh or (vertices, faces) pair, any object with
    ``vertices`` and ``faces`` (a trimesh.Trimesh), or vertex and face arrays; path is None unless
    the mesh was read from a file."""
    if faces is None:
        if isinstance(mesh, (str, os.PathLike)):
            path = os.fspath(mesh)
            vertices, faces = _core.read_mesh(path)
            return vertices, faces, path
        if hasattr(mesh, "vertices") and hasattr(mesh, "faces"):
            mesh, faces = mesh.vertices, mesh.faces
        elif isinstance(mesh, (tuple, list)) and len(mesh) == 2:
            mesh, faces = mesh
        else:
            raise TypeError("expected a path, a (vertices, faces) pair, an object with .vertices and .faces, "
                            f"or vertex and face arrays; got {type(mesh).__name__}")
    vertices, faces = checked_arrays(mesh, faces)
    return vertices, faces, None


def meshes(pairs):
    """[Mesh] from the extension's [(vertices, faces)]."""
    return [Mesh(v, f) for v, f in pairs]


def read_mesh(path):
    """Reads OFF, OBJ, PLY (ASCII or binary) or STL (ASCII or binary) into a Mesh; polygons are
    fan-triangulated. Raises acd.Error (a ValueError) with the library's message."""
    return Mesh(*_core.read_mesh(os.fspath(path)))


def write_mesh(path, mesh, faces=None):
    """Writes a mesh by the file's extension (.off, .obj, .ply, .stl)."""
    vertices, faces, _ = resolve(mesh, faces)
    _core.write_mesh(os.fspath(path), vertices, faces)

"""acd: approximate convex decomposition of polyhedra (Lien & Amato, SPM 2007).

    import acd
    parts, hulls, report = acd.decompose("model.off", tau=0.05)

Meshes are numpy arrays: vertices (n, 3) float64, faces (m, 3) int64 (acd.Mesh). Keyword
arguments are the options of the ``acd`` command, with the same names ('-' becomes '_') and
defaults. Lengths are in normalised units (minimum enclosing sphere radius 1); output meshes are
in the input's coordinates. A mesh or parameter the library refuses raises acd.Error, a
ValueError whose ``code`` is an acd.StatusCode.
"""
from ._core import Error, StatusCode, __version__
from ._meshes import Mesh, read_mesh, write_mesh
from ._api import (Decomposition, MeshDecomposition, SurfaceDecomposition, decompose, decompose_exact,
                   decompose_surface, diagnose, evaluate, write_simulator_files)

Error.__module__ = __name__

__all__ = ["Decomposition", "Error", "Mesh", "MeshDecomposition", "StatusCode", "SurfaceDecomposition",
           "__version__", "decompose", "decompose_exact", "decompose_surface", "diagnose", "evaluate", "read_mesh",
           "write_mesh", "write_simulator_files"]

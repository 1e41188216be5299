"""The functions of the acd package: decompose (with its modes: per_mesh, surface, exact),
write_simulator_files, decompose_surface, decompose_exact, evaluate, diagnose."""
import json
import os
import sys
import warnings
from typing import List, NamedTuple, Optional

import numpy as np

from . import _core
from ._meshes import Mesh, meshes, resolve
from ._options import build, keywords, with_options


class Decomposition(NamedTuple):
    """Solid ACD: ``components`` (closed, outward Mesh each, input coordinates), ``hulls``
    (their convex hulls, same order) and ``report`` (report.json of ``acd decompose`` as a dict)."""

    components: List[Mesh]
    hulls: List[Mesh]
    report: dict


class SurfaceDecomposition(NamedTuple):
    """Surface ACD: ``components`` (the patches, open meshes in input coordinates), ``hulls``
    (one per patch; empty arrays for a flat patch), ``report`` (report.json of
    ``acd decompose --surface``), ``surface`` (the input after repairs) and ``patch_faces``
    (each patch's face indices into ``surface``; together every face once)."""

    components: List[Mesh]
    hulls: List[Mesh]
    report: dict
    surface: Mesh
    patch_faces: List[np.ndarray]


class MeshDecomposition(NamedTuple):
    """One mesh of a scene file decomposed on its own (``decompose(path, per_mesh=True)``, as
    ``acd decompose --per-mesh``): ``name`` ("node/mesh", report["mesh"], the NAME of the command's
    OUT/NNN_NAME/ folder), ``decomposition`` (a Decomposition, None when the mesh was refused)
    and ``error`` (the acd.Error that refused it, else None): a refused mesh does not stop the others."""

    name: str
    decomposition: Optional[Decomposition]
    error: Optional[_core.Error]


def _report(text, path):
    report = json.loads(text)
    report["model"] = path  # None for arrays
    return report


_PACKAGE = os.path.dirname(os.path.abspath(__file__))


def _warn_caller(message):
    """A RuntimeWarning pointing at the first caller outside the package, however deep the routing."""
    level, frame = 2, sys._getframe(1)
    while frame is not None and os.path.dirname(os.path.abspath(frame.f_code.co_filename)) == _PACKAGE:
        level, frame = level + 1, frame.f_back
    warnings.warn(message, RuntimeWarning, stacklevel=level)


def _warn(report, what):
    # The command line's warnings, as Python warnings.
    mesh = f"mesh {report['mesh']}: " if "mesh" in report else ""
    pairs = report["input"]["self_intersecting_face_pairs"]
    if pairs > 0:
        _warn_caller(f"{mesh}the model intersects itself ({pairs} face pairs); {what} where it does")
    if report["totals"]["unresolved"] > 0:
        _warn_caller(f"{mesh}{report['totals']['unresolved']} component(s) still exceed tau "
                     "(marked unresolved in the report)")
    budget = report.get("hull_budget")
    if budget and budget["exceeds_tau"] and budget["components_after"] < budget["components_before"]:
        _warn_caller(f"{mesh}max_hulls={budget['max_hulls']}: merging {budget['components_before']} components into "
                     f"{budget['components_after']} reached concavity {budget['max_concavity']:.4g}, above "
                     f"tau = {budget['tau']:g} (report['hull_budget'])")


def _given(options, options_class):
    """The keywords given that another mode's function takes (the others keep their defaults)."""
    names = keywords(options_class)
    return {name: value for name, value in options.items() if name in names}


@with_options(_core.DecomposeOptions)
def decompose(mesh, faces=None, *, progress=None, **options):
    """Solid approximate convex decomposition: every component ends with concavity <= tau
    (normalised units: the model scaled so that its minimum enclosing sphere has radius 1).
    Returns a Decomposition.

    ``mesh``: a path (OFF, OBJ, PLY, STL; glTF, GLB, COLLADA, 3MF, FBX, whose meshes are merged
    into one model), a Mesh or (vertices, faces) pair, an object with ``vertices`` and ``faces``
    (a trimesh.Trimesh), or an (n, 3) float array with ``faces`` an (m, 3) int array.
    ``progress(done, pending)`` is called after each round of cuts.
    The GIL is released while the library works. Bad input or parameters raise acd.Error (a
    ValueError) with the library's message; an exception from ``progress`` is raised when the
    decomposition finishes.

    For simulators, as on the command line: ``tau_abs`` (tau as a length in the input's units,
    instead of ``tau``), ``max_hulls`` (merge components until at most N remain),
    ``max_hull_vertices`` (every hull replaced by a containing polytope of at most K >= 4
    corners) and ``density`` (report["mass_properties"]); None: not applied.
    ``write_simulator_files`` writes the result as URDF, MJCF, SDF, glTF, OBJ or STL.

    The command's other modes, with its flags: ``per_mesh=True`` decomposes every mesh of a
    scene file (or every object of an OBJ) on its own and returns a list of MeshDecomposition;
    ``surface=True`` is decompose_surface; ``exact=True`` is decompose_exact (with
    ``exact_time_limit``, ``exact_memory``, ``exact_tolerance``, ``surface``, ``no_fill_holes``).
    Options a mode does not use are ignored, as on the command line.
    """
    settings = build(_core.DecomposeOptions, options, "decompose")
    _core.validate(settings)  # before reading the model, as the command does
    if settings.exact:
        return decompose_exact(mesh, faces, progress=progress, **_given(options, _core.ExactOptions))
    if settings.surface:
        return decompose_surface(mesh, faces, progress=progress, **_given(options, _core.SurfaceDecomposeOptions))
    if settings.per_mesh:
        return _decompose_per_mesh(mesh, faces, settings, progress)
    vertices, faces, path = resolve(mesh, faces)
    parts, hulls, text = _core.decompose(vertices, faces, settings, path or "", "", progress)
    report = _report(text, path)
    _warn(report, "pieces whose sections cross themselves may stay above tau")
    return Decomposition(meshes(parts), meshes(hulls), report)


def _decompose_per_mesh(path, faces, settings, progress):
    """``acd decompose --per-mesh``: each mesh of the file decomposed with tau in its own normalised units."""
    if faces is not None or not isinstance(path, (str, os.PathLike)):
        raise TypeError("per_mesh=True decomposes the meshes of a file: give its path")
    path = os.fspath(path)
    results = []
    for name, (vertices, mesh_faces) in _core.read_scene_meshes(path):
        try:
            parts, hulls, text = _core.decompose(vertices, mesh_faces, settings, path, name, progress)
        except _core.Error as error:
            _warn_caller(f"mesh {name}: {error}")
            results.append(MeshDecomposition(name, None, error))
            continue
        report = _report(text, path)
        _warn(report, "pieces whose sections cross themselves may stay above tau")
        results.append(MeshDecomposition(name, Decomposition(meshes(parts), meshes(hulls), report), None))
    return results


def write_simulator_files(folder, decomposition, model, formats=("urdf",), *, name=None, model_faces=None):
    """The files of ``acd decompose --format`` for a Decomposition, written into ``folder``
    (created if needed): ``formats`` among "obj", "stl" (one file per hull), "glb", "gltf",
    "urdf", "mjcf", "sdf" (docs/SIMULATORS.md has the layout). ``model``: the mesh that was
    decomposed, as for decompose (``model_faces`` with a vertex array), the visual of URDF, MJCF
    and SDF; ``name``: the body's name (default: the model file's name, else "model"). Mass and
    inertia are the components' at the density the decomposition used. Returns the paths written,
    relative to ``folder``.
    """
    if isinstance(formats, str):
        formats = formats.split(",")
    vertices, faces, path = resolve(model, model_faces)
    if name is None:
        name = os.path.splitext(os.path.basename(path))[0] if path else "model"
    density = decomposition.report["mass_properties"]["density"]
    folder = os.fspath(folder)
    os.makedirs(folder, exist_ok=True)
    return _core.write_simulator_files(folder, name, (vertices, faces), [tuple(h) for h in decomposition.hulls],
                                       [tuple(c) for c in decomposition.components], density, list(formats))


@with_options(_core.SurfaceDecomposeOptions)
def decompose_surface(mesh, faces=None, *, progress=None, **options) -> SurfaceDecomposition:
    """Surface ACD (Section 4.3 of the paper): the surface is split along global cuts into
    patches whose concavity is at most tau; open meshes stay open. Arguments as for decompose.
    """
    settings = build(_core.SurfaceDecomposeOptions, options, "decompose_surface")
    _core.validate(settings)
    vertices, faces, path = resolve(mesh, faces)
    patches, hulls, text, surface, patch_faces = _core.decompose_surface(vertices, faces, settings, path or "",
                                                                          progress)
    report = _report(text, path)
    _warn(report, "the patches intersect")
    return SurfaceDecomposition(meshes(patches), meshes(hulls), report, Mesh(*surface), list(patch_faces))


@with_options(_core.ExactOptions)
def decompose_exact(mesh, faces=None, *, progress=None, **options):
    """Exact convex decomposition, the baseline of ``acd decompose --exact``: interior-disjoint
    convex pieces whose union is the model (CGAL's convex_decomposition_3), returned as a
    Decomposition whose ``hulls`` are the pieces themselves (a convex piece is its own hull).
    With ``surface=True`` (``--exact --surface``): convex surface patches, as a
    SurfaceDecomposition whose ``surface`` is the input. Arguments as for decompose.

    The solid decomposition runs in a worker process that ``exact_time_limit`` (seconds, 0: none)
    and ``exact_memory`` (GiB of address space, 0: none) cap; a cap that stops it is no error:
    report["totals"]["finished"] is False, report["totals"]["note"] says where it stopped, and a
    RuntimeWarning says so (the command exits with 4). ``progress(stage, seconds)`` is called
    about once a second. ``exact_tolerance``: how far a vertex may lie beyond a patch face's plane
    (surface only, normalised units).
    """
    settings = build(_core.ExactOptions, options, "decompose_exact")
    _core.validate(settings)
    vertices, faces, path = resolve(mesh, faces)
    if settings.surface:
        patches, hulls, text, patch_faces = _core.decompose_exact_surface(vertices, faces, settings, path or "")
        return SurfaceDecomposition(meshes(patches), meshes(hulls), _report(text, path), Mesh(vertices, faces),
                                    list(patch_faces))
    pieces, text = _core.decompose_exact(vertices, faces, settings, path or "", progress)
    report = _report(text, path)
    if not report["totals"]["finished"]:
        _warn_caller(f"exact decomposition not finished: {report['totals']['note']}")
    pieces = meshes(pieces)
    return Decomposition(pieces, pieces, report)


@with_options(_core.EvaluateOptions)
def evaluate(model, hulls, *, model_faces=None, **options) -> dict:
    """How well a set of convex hulls approximates a closed model, as ``acd evaluate --json``
    (normalised units; volumes are Monte-Carlo estimates with standard errors).

    ``model``: as ``mesh`` for decompose (``model_faces`` with a vertex array). ``hulls``: an OBJ
    path (one object per hull), a Decomposition, or a sequence of meshes; every hull is replaced by
    the convex hull of its vertices.
    """
    settings = build(_core.EvaluateOptions, options, "evaluate")
    vertices, faces, path = resolve(model, model_faces)
    hulls_file = None
    if isinstance(hulls, (str, os.PathLike)):
        hulls_file = os.fspath(hulls)
        pairs = _core.read_obj_objects(hulls_file)
    else:
        if isinstance(hulls, (Decomposition, SurfaceDecomposition)):
            hulls = [h for h in hulls.hulls if len(h.faces) > 0]
        pairs = [resolve(h)[:2] for h in hulls]
    result = json.loads(_core.evaluate(vertices, faces, pairs, settings, path or "", hulls_file or ""))
    result["model"], result["hulls_file"] = path, hulls_file
    return result


def diagnose(mesh, faces=None) -> dict:
    """What ``acd info`` prints, as a dict: counts of vertices, faces, edges, boundary and
    non-manifold elements, degenerate and duplicate faces, orientation, closedness, genus (None when
    undefined), volume and area (input units), bbox, the first problem found, self-intersecting face
    pairs (None when not counted), whether a solid decomposition is possible and the repairs it needs.
    Never raises for a bad mesh: that is what it reports.
    """
    vertices, faces, path = resolve(mesh, faces)
    result = _core.diagnose(vertices, faces)
    result["model"] = path
    return result


__all__ = ["Decomposition", "MeshDecomposition", "SurfaceDecomposition", "decompose", "decompose_exact",
           "decompose_surface", "evaluate", "diagnose", "write_simulator_files"]
